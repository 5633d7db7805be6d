// Escaping for the lecture page: HTML text, URL paths, JSON inside <script>, base64.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace vibra::render {

/// Escapes &, <, >, " and ' for HTML text and attributes.
std::string html_escape(const std::string&);

/// A relative file path made safe as a URL path: every byte but the
/// unreserved ones (A-Z a-z 0-9 - . _ ~) and '/' percent-encoded, so names
/// with spaces, '#', '?' or non-ASCII characters (UTF-8) link correctly.
std::string url_path_escape(const std::string& path);

/// A JSON string literal (quotes included). '<' is written \u003c so the
/// text can sit inside a <script> element without ending it.
std::string json_string(const std::string&);

/// Standard base64 (RFC 4648, with padding).
std::string base64(std::span<const std::uint8_t> bytes);

}  // namespace vibra::render
