// Tests of the YUV 4:2:0 converter: BT.709 values, agreement with swscale, changed blocks only.
extern "C" {
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "argb_image.hpp"
#include "render/encode/pixels/yuv420_converter.hpp"

using vibra::render::Yuv420Converter;
using vibra::render::Yuv420Planes;

namespace {

/// White, with padded rows.
struct Image : vibra::test::ArgbImage {
  Image(int w, int h, std::uint32_t fill = 0xffffffffu) : ArgbImage(w, h, 2, fill) {}
};

/// The planes of a conversion.
struct Yuv {
  int width, height, chroma_width, chroma_height;
  std::vector<std::uint8_t> y, u, v;
  Yuv(int w, int h)
      : width(w), height(h), chroma_width((w + 1) / 2), chroma_height((h + 1) / 2),
        y(std::size_t(w) * h), u(std::size_t(chroma_width) * chroma_height), v(u.size()) {}
  Yuv420Planes planes() { return {{y.data(), u.data(), v.data()}, {width, chroma_width, chroma_width}}; }
  bool operator==(const Yuv& o) const { return y == o.y && u == o.u && v == o.v; }
};

Yuv convert_once(const Image& image, int out_width, int out_height) {
  Yuv out(out_width, out_height);
  Yuv420Converter(image.width, image.height, out_width, out_height).convert(image.bytes(), image.stride, out.planes());
  return out;
}

std::uint32_t argb(int r, int g, int b) { return 0xff000000u | std::uint32_t(r) << 16 | std::uint32_t(g) << 8 | b; }

}  // namespace

TEST_CASE("yuv420: BT.709 limited range gives the standard values of the primaries", "[yuv]") {
  struct Case {
    std::uint32_t color;
    int y, u, v;
  };
  // ITU-R BT.709 in 8-bit "tv" range: Y 16..235, Cb and Cr 16..240.
  const Case cases[] = {{argb(255, 255, 255), 235, 128, 128}, {argb(0, 0, 0), 16, 128, 128},
                        {argb(255, 0, 0), 63, 102, 240},      {argb(0, 255, 0), 173, 42, 26},
                        {argb(0, 0, 255), 32, 240, 118},      {argb(128, 128, 128), 126, 128, 128},
                        {0x00000000u, 16, 128, 128}};  // transparent (premultiplied): black
  for (const Case& c : cases) {
    INFO(std::hex << c.color);
    const Yuv out = convert_once(Image(6, 4, c.color), 6, 4);
    for (std::uint8_t y : out.y) CHECK(int(y) == c.y);
    for (std::uint8_t u : out.u) CHECK(int(u) == c.u);
    for (std::uint8_t v : out.v) CHECK(int(v) == c.v);
  }
}

TEST_CASE("yuv420: agrees with swscale's BT.709 conversion on smooth pictures", "[yuv]") {
  const int w = 96, h = 64;
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = argb(x * 255 / (w - 1), y * 255 / (h - 1), (x + y) * 255 / (w + h - 2));
  const Yuv ours = convert_once(image, w, h);

  Yuv reference(w, h);
  SwsContext* sws = sws_getContext(w, h, AV_PIX_FMT_RGB32, w, h, AV_PIX_FMT_YUV420P,
                                   SWS_BILINEAR | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
  REQUIRE(sws != nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  REQUIRE(sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16) >= 0);
  const std::uint8_t* source[1] = {image.bytes()};
  const int source_stride[1] = {image.stride};
  Yuv420Planes planes = reference.planes();
  sws_scale(sws, source, source_stride, 0, h, planes.data, planes.linesize);
  sws_freeContext(sws);

  int luma_error = 0, chroma_error = 0;
  for (std::size_t i = 0; i < ours.y.size(); ++i) luma_error = std::max(luma_error, std::abs(ours.y[i] - reference.y[i]));
  // Chroma rows at the picture's edges depend on how a library pads its
  // filter; compare the inside.
  for (int y = 1; y < reference.chroma_height - 1; ++y)
    for (int x = 1; x < reference.chroma_width - 1; ++x) {
      const std::size_t i = std::size_t(y) * reference.chroma_width + x;
      chroma_error = std::max({chroma_error, std::abs(ours.u[i] - reference.u[i]), std::abs(ours.v[i] - reference.v[i])});
    }
  CHECK(luma_error <= 1);
  CHECK(chroma_error <= 2);
}

TEST_CASE("yuv420: converting only the changed blocks gives exactly a full conversion", "[yuv]") {
  const int w = 200, h = 90;  // not multiples of the block width
  std::mt19937 random(7);
  Image image(w, h);
  for (auto& p : image.words) p = 0xff000000u | (random() & 0xffffffu);
  Yuv420Converter converter(w, h, w, h);
  Yuv out(w, h);
  converter.convert(image.bytes(), image.stride, out.planes());
  CHECK(converter.converted_blocks() == converter.blocks());
  CHECK(out == convert_once(image, w, h));

  converter.convert(image.bytes(), image.stride, out.planes());
  CHECK(converter.converted_blocks() == 0);  // nothing changed
  CHECK(out == convert_once(image, w, h));

  for (int frame = 0; frame < 5; ++frame) {
    for (int k = 0; k < 20; ++k)  // a few scattered pixels, as a swinging rod changes
      image.at(int(random() % w), int(random() % h)) = 0xff000000u | (random() & 0xffffffu);
    converter.convert(image.bytes(), image.stride, out.planes());
    CHECK(converter.converted_blocks() > 0);
    CHECK(converter.converted_blocks() <= 40);
    CHECK(out == convert_once(image, w, h));
  }
}

TEST_CASE("yuv420: with damage given, only the damaged blocks are looked at", "[yuv]") {
  const int w = 128, h = 64;
  Image image(w, h);
  Yuv420Converter converter(w, h, w, h);
  Yuv out(w, h);
  converter.convert(image.bytes(), image.stride, out.planes());

  image.at(10, 10) = argb(255, 0, 0);  // inside the damage
  image.at(100, 50) = argb(0, 0, 255);  // outside it: the caller promised nothing changed there
  vibra::render::Damage changed(w, h);
  changed.add(8, 8, 12, 12, 0);
  converter.convert(image.bytes(), image.stride, out.planes(), &changed);
  CHECK(converter.converted_blocks() == 1);
  CHECK(int(out.y[10 * w + 10]) == 63);   // red
  CHECK(int(out.y[50 * w + 100]) == 235);  // still white: not looked at

  vibra::render::Damage nothing(w, h);
  converter.convert(image.bytes(), image.stride, out.planes(), &nothing);
  CHECK(converter.converted_blocks() == 0);
  changed.add_all();
  converter.convert(image.bytes(), image.stride, out.planes(), &changed);
  CHECK(converter.converted_blocks() == 1);  // the blue pixel's block, found by comparing
  CHECK(out == convert_once(image, w, h));
}

TEST_CASE("yuv420: outputs that come round again get the blocks converted since they were last written",
          "[yuv]") {
  // An encoder's queue hands the converter its frames in turn; each must end
  // up as a full conversion of the latest picture, odd sizes included.
  for (const auto& [w, h, out_w, out_h] : {std::array{200, 90, 200, 90}, std::array{75, 41, 76, 42}, std::array{75, 41, 75, 41}}) {
    INFO(w << "x" << h << " into " << out_w << "x" << out_h);
    std::mt19937 random(11);
    Image image(w, h);
    Yuv420Converter converter(w, h, out_w, out_h);
    std::vector<Yuv> outputs(3, Yuv(out_w, out_h));
    std::vector<std::uint64_t> holds(outputs.size(), 0);
    for (int frame = 0; frame < 12; ++frame) {
      vibra::render::Damage changed(w, h);
      for (int k = 0; k < 3; ++k) {  // a few small changes, each inside the damage given
        const int x = int(random() % w), y = int(random() % h);
        image.at(x, y) = argb(int(random() % 256), 40, 200);
        changed.add(x, y, x + 1, y + 1, 0);
      }
      if (frame == 7) changed.add_all();
      Yuv& out = outputs[frame % outputs.size()];
      converter.convert(image.bytes(), image.stride, out.planes(), frame == 0 ? nullptr : &changed,
                        &holds[frame % outputs.size()]);
      CHECK(out == convert_once(image, out_w, out_h));
    }
  }
}

TEST_CASE("yuv420: an output that holds the last conversion is not copied into again", "[yuv]") {
  const int w = 128, h = 64;
  Image image(w, h);
  Yuv420Converter converter(w, h, w, h);
  Yuv out(w, h);
  std::uint64_t holds = 0;
  converter.convert(image.bytes(), image.stride, out.planes(), nullptr, &holds);
  CHECK(holds > 0);
  out.y[60 * w + 100] = 7;  // a mark where nothing will change
  image.at(10, 10) = argb(255, 0, 0);
  vibra::render::Damage changed(w, h);
  changed.add(8, 8, 12, 12, 0);
  converter.convert(image.bytes(), image.stride, out.planes(), &changed, &holds);
  CHECK(int(out.y[10 * w + 10]) == 63);  // the changed block copied
  CHECK(int(out.y[60 * w + 100]) == 7);  // the rest left as it was
  std::uint64_t unknown = 0;  // an output of unknown pixels gets everything
  converter.convert(image.bytes(), image.stride, out.planes(), &changed, &unknown);
  CHECK(int(out.y[60 * w + 100]) == 235);
}

TEST_CASE("yuv420: an odd size is padded by repeating the last column and row", "[yuv]") {
  Image image(7, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) image.at(x, y) = argb(30 * x, 40 * y, 100);

  const Yuv even = convert_once(image, 8, 6);  // H.264
  for (int y = 0; y < 6; ++y) CHECK(even.y[std::size_t(y) * 8 + 7] == even.y[std::size_t(y) * 8 + 6]);
  for (int x = 0; x < 8; ++x) CHECK(even.y[5 * 8 + x] == even.y[4 * 8 + x]);

  const Yuv odd = convert_once(image, 7, 5);  // VP9 and the others keep the size
  REQUIRE(odd.chroma_width == 4);
  REQUIRE(odd.chroma_height == 3);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 7; ++x) CHECK(odd.y[std::size_t(y) * 7 + x] == even.y[std::size_t(y) * 8 + x]);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) CHECK(odd.u[std::size_t(y) * 4 + x] == even.u[std::size_t(y) * 4 + x]);

  CHECK_THROWS_AS(Yuv420Converter(7, 5, 9, 5), std::invalid_argument);
  CHECK_THROWS_AS(Yuv420Converter(0, 5, 0, 5), std::invalid_argument);
}
