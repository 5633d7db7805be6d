// libFuzzer target: vibra::fuzz::formula (see fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  vibra::fuzz::formula(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
