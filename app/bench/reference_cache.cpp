#include "app/bench/reference_cache.h"

namespace ml::app {

const ReferenceImages* ReferenceCache::find(const std::string& frameKey) {
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
        if (it->first != frameKey) continue;
        entries_.splice(entries_.begin(), entries_, it);
        return &entries_.front().second;
    }
    return nullptr;
}

const ReferenceImages& ReferenceCache::insert(const std::string& frameKey, ReferenceImages images) {
    bytes_ += images.bytes();
    entries_.emplace_front(frameKey, std::move(images));
    while (bytes_ > maxBytes_ && entries_.size() > 1) {
        bytes_ -= entries_.back().second.bytes();
        entries_.pop_back();
    }
    return entries_.front().second;
}

}  // namespace ml::app
