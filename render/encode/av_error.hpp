// FFmpeg's text for an error code, for one-line error messages.
#pragma once
extern "C" {
#include <libavutil/error.h>
}

#include <string>

namespace vibra::render {

/// FFmpeg's text for an error code, e.g. "No space left on device".
inline std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

}  // namespace vibra::render
