// The files of a remux (packets copied without decoding): an input opened with libavformat, an output written under a temporary name, and the check that two video streams can follow each other in one file.
#include "render/encode/join/remux_files.hpp"

#include <cstring>

#include "render/encode/av_error.hpp"
#include "render/output/output_error.hpp"

namespace vibra::render {

MediaInput open_media_input(const std::filesystem::path& path, std::string& error) {
  AVFormatContext* context = nullptr;
  const int opened = avformat_open_input(&context, path.c_str(), nullptr, nullptr);
  if (opened < 0) {
    error = av_error(opened);
    return nullptr;
  }
  return MediaInput(context);
}

std::string container_metadata(const AVFormatContext* context, const char* key) {
  const AVDictionaryEntry* entry = av_dict_get(context->metadata, key, nullptr, 0);
  return entry ? entry->value : "";
}

std::string quoted_path(const std::filesystem::path& path) {
  std::string text = "'";  // built in steps: GCC 12 warns falsely about "'" + string (bug 105329)
  text += path.string();
  return text += "'";
}

AVRational stream_frame_rate(const AVStream* stream) {
  const AVRational rate = stream->avg_frame_rate.num > 0 ? stream->avg_frame_rate : stream->r_frame_rate;
  return rate.num > 0 && rate.den > 0 ? rate : AVRational{0, 1};
}

std::string differing_video_parameter(const AVStream* a, const AVStream* b) {
  const AVCodecParameters *p = a->codecpar, *q = b->codecpar;
  if (p->codec_id != q->codec_id)
    return std::string("codec ") + avcodec_get_name(q->codec_id) + " instead of " + avcodec_get_name(p->codec_id);
  if (p->width != q->width || p->height != q->height)
    return "size " + std::to_string(q->width) + "x" + std::to_string(q->height) + " instead of " +
           std::to_string(p->width) + "x" + std::to_string(p->height);
  if (p->format != q->format) return "another pixel format";
  if (av_cmp_q(a->time_base, b->time_base) != 0) return "another time base";
  if (av_cmp_q(stream_frame_rate(a), stream_frame_rate(b)) != 0)
    return "frame rate " + std::to_string(av_q2d(stream_frame_rate(b))) + " instead of " +
           std::to_string(av_q2d(stream_frame_rate(a)));
  if (p->extradata_size != q->extradata_size ||
      (p->extradata_size > 0 && std::memcmp(p->extradata, q->extradata, p->extradata_size) != 0))
    return "other codec headers (another quality, preset or profile)";
  if (p->color_range != q->color_range || p->color_space != q->color_space) return "another colour space";
  return "";
}

MuxedOutput::~MuxedOutput() {
  if (format) {
    if (format->pb) avio_closep(&format->pb);
    avformat_free_context(format);
  }
}

void MuxedOutput::check(int code, const std::string& what) const {
  if (code < 0)
    throw OutputError("cannot write " + quoted_path(file.final_path()) + ": " + what + " failed (" + av_error(code) +
                      "): check that the disk is writable and has space");
}

void MuxedOutput::open(const AVOutputFormat* muxer) {
  check(avformat_alloc_output_context2(&format, muxer, nullptr, file.path().c_str()), "setting up");
}

void MuxedOutput::write_header() {
  check(avio_open(&format->pb, file.path().c_str(), AVIO_FLAG_WRITE), "opening the file");
  AVDictionary* header = nullptr;
  if (std::strcmp(format->oformat->name, "mp4") == 0) av_dict_set(&header, "movflags", "+faststart", 0);
  const int written = avformat_write_header(format, &header);
  av_dict_free(&header);
  check(written, "writing the header");
}

void MuxedOutput::finish_and_commit() {
  check(av_write_trailer(format), "writing the trailer");
  check(avio_closep(&format->pb), "closing the file");
  file.commit();
}

}  // namespace vibra::render
