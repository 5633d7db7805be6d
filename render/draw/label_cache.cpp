// LabelCache: labels of an image canvas laid out once and kept as images, pasted on later frames.
#include "render/draw/label_cache.hpp"

namespace vibra::render {

LabelCache::Label* LabelCache::find(const std::string& key) {
  auto it = labels_.find(key);
  return it == labels_.end() ? nullptr : &it->second;
}

LabelCache::Label& LabelCache::keep(const std::string& key, Label label) {
  if (used_ > budget_ || labels_.size() >= most_labels_) labels_.clear(), used_ = 0;
  return labels_.insert_or_assign(key, std::move(label)).first->second;
}

}  // namespace vibra::render
