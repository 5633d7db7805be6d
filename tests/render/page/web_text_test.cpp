// Escaping for the lecture page: HTML, URL paths, JSON inside <script>, base64.
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "render/page/web_text.hpp"

using namespace vibra::render;

TEST_CASE("html_escape escapes markup and both quotes", "[page]") {
  CHECK(html_escape("a<b & \"c\" 'd'>") == "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  CHECK(html_escape("Pendel ø") == "Pendel ø");  // UTF-8 passes through
}

TEST_CASE("url_path_escape percent-encodes all but unreserved bytes and slashes", "[page]") {
  CHECK(url_path_escape("Pendel ø.mp4") == "Pendel%20%C3%B8.mp4");
  CHECK(url_path_escape("a#b?c%d&e.csv") == "a%23b%3Fc%25d%26e.csv");
  CHECK(url_path_escape("x_frames/frame_") == "x_frames/frame_");
  CHECK(url_path_escape("A-Z_a.z~0") == "A-Z_a.z~0");
}

TEST_CASE("json_string escapes quotes, controls and '<' (a script cannot be ended early)", "[page]") {
  CHECK(json_string("θ (degrees)") == "\"θ (degrees)\"");
  CHECK(json_string("a\"b\\c\nd\x01") == "\"a\\\"b\\\\c\\nd\\u0001\"");
  CHECK(json_string("</script><!--") == "\"\\u003c/script>\\u003c!--\"");
}

TEST_CASE("base64 matches RFC 4648's test vectors", "[page]") {
  auto encode = [](const std::string& text) {
    return base64(std::vector<std::uint8_t>(text.begin(), text.end()));
  };
  CHECK(encode("") == "");
  CHECK(encode("f") == "Zg==");
  CHECK(encode("fo") == "Zm8=");
  CHECK(encode("foo") == "Zm9v");
  CHECK(encode("foob") == "Zm9vYg==");
  CHECK(encode("fooba") == "Zm9vYmE=");
  CHECK(encode("foobar") == "Zm9vYmFy");
  CHECK(base64(std::vector<std::uint8_t>{0xff, 0xfe, 0x00}) == "//4A");
}
