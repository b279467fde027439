#include "source/edit.h"

#include <algorithm>

namespace shaderport {

bool EditsOverlap(const Edit& a, const Edit& b) {
  if (a.begin < b.end && b.begin < a.end) return true;
  // An insertion strictly inside the other edit's replaced range.
  if (a.begin == a.end && b.begin < a.begin && a.begin < b.end) return true;
  if (b.begin == b.end && a.begin < b.begin && b.begin < a.end) return true;
  return false;
}

SourceMap SourceMap::Identity(uint32_t size) {
  SourceMap map;
  map.SetSizes(size, size);
  if (size > 0) map.Append({0, size, 0, size, false});
  return map;
}

void SourceMap::Append(MapSegment segment) {
  if (segment.length == 0 && !segment.inserted) return;
  if (segment.length == 0) return;  // an empty insertion (a deletion) leaves no output
  if (!segments_.empty()) {
    MapSegment& last = segments_.back();
    const bool contiguous = last.output_begin + last.length == segment.output_begin;
    if (contiguous && !last.inserted && !segment.inserted &&
        last.original_end == segment.original_begin) {
      last.length += segment.length;
      last.original_end = segment.original_end;
      return;
    }
    if (contiguous && last.inserted && segment.inserted &&
        last.original_begin == segment.original_begin &&
        last.original_end == segment.original_end) {
      last.length += segment.length;
      return;
    }
  }
  segments_.push_back(segment);
}

const MapSegment* SourceMap::SegmentAt(uint32_t offset) const {
  auto it = std::upper_bound(
      segments_.begin(), segments_.end(), offset,
      [](uint32_t value, const MapSegment& segment) { return value < segment.output_begin; });
  if (it == segments_.begin()) return nullptr;
  --it;
  if (offset >= it->output_begin + it->length) return nullptr;
  return &*it;
}

uint32_t SourceMap::ToOriginal(uint32_t offset) const {
  if (offset >= output_size_) return original_size_;
  const MapSegment* segment = SegmentAt(offset);
  if (segment == nullptr) return original_size_;
  if (segment->inserted) return segment->original_begin;
  return segment->original_begin + (offset - segment->output_begin);
}

std::pair<uint32_t, uint32_t> SourceMap::ToOriginalRange(uint32_t begin, uint32_t end) const {
  if (end < begin) end = begin;
  uint32_t original_begin = ToOriginal(begin);
  uint32_t original_end = original_begin;
  if (end > begin) {
    const MapSegment* last = SegmentAt(end - 1);
    if (last == nullptr) {
      original_end = original_size_;
    } else if (last->inserted) {
      original_end = last->original_end;
    } else {
      original_end = last->original_begin + (end - 1 - last->output_begin) + 1;
    }
  }
  if (const MapSegment* first = SegmentAt(begin); first != nullptr && first->inserted) {
    original_begin = first->original_begin;
  }
  if (original_end < original_begin) original_end = original_begin;
  return {original_begin, original_end};
}

bool SourceMap::IsCopied(uint32_t begin, uint32_t end) const {
  if (begin == end) {
    // An empty range is a copy when it sits in or at the edge of copied text.
    if (begin >= output_size_) return true;
    const MapSegment* segment = SegmentAt(begin);
    return segment != nullptr && !segment->inserted;
  }
  const MapSegment* segment = SegmentAt(begin);
  return segment != nullptr && !segment->inserted && end <= segment->output_begin + segment->length;
}

SourceMap SourceMap::Compose(const SourceMap& first, const SourceMap& second) {
  SourceMap result;
  result.SetSizes(first.original_size_, second.output_size_);
  for (const MapSegment& outer : second.segments_) {
    if (outer.inserted) {
      const auto [begin, end] = first.ToOriginalRange(outer.original_begin, outer.original_end);
      result.Append({outer.output_begin, outer.length, begin, end, true});
      continue;
    }
    // A copied run of the middle text may cross several segments of `first`.
    uint32_t done = 0;
    while (done < outer.length) {
      const uint32_t middle = outer.original_begin + done;
      const MapSegment* inner = first.SegmentAt(middle);
      if (inner == nullptr) break;  // cannot happen for maps made by ApplyEdits
      const uint32_t inner_offset = middle - inner->output_begin;
      const uint32_t take = std::min(outer.length - done, inner->length - inner_offset);
      if (inner->inserted) {
        result.Append(
            {outer.output_begin + done, take, inner->original_begin, inner->original_end, true});
      } else {
        const uint32_t begin = inner->original_begin + inner_offset;
        result.Append({outer.output_begin + done, take, begin, begin + take, false});
      }
      done += take;
    }
  }
  return result;
}

std::optional<EditResult> ApplyEdits(std::string_view original, std::span<const Edit> edits) {
  std::vector<const Edit*> sorted;
  sorted.reserve(edits.size());
  for (const Edit& edit : edits) {
    if (edit.begin > edit.end || edit.end > original.size()) return std::nullopt;
    sorted.push_back(&edit);
  }
  // At one offset, insertions go before a replacement that starts there (they
  // cannot overlap it); among insertions the callers' order is kept.
  std::stable_sort(sorted.begin(), sorted.end(), [](const Edit* a, const Edit* b) {
    if (a->begin != b->begin) return a->begin < b->begin;
    return a->begin == a->end && b->begin != b->end;
  });
  for (size_t i = 1; i < sorted.size(); ++i) {
    if (EditsOverlap(*sorted[i - 1], *sorted[i])) return std::nullopt;
  }
  // Sorted and disjoint, but an insertion at X may follow a replacement [.., X).
  EditResult result;
  const auto original_size = static_cast<uint32_t>(original.size());
  uint32_t cursor = 0;
  auto output_size = [&] { return static_cast<uint32_t>(result.text.size()); };
  for (const Edit* edit : sorted) {
    if (edit->begin < cursor) return std::nullopt;
    if (edit->begin > cursor) {
      result.map.Append({output_size(), edit->begin - cursor, cursor, edit->begin, false});
      result.text.append(original.substr(cursor, edit->begin - cursor));
    }
    const auto length = static_cast<uint32_t>(edit->text.size());
    result.map.Append({output_size(), length, edit->begin, edit->end, true});
    result.text.append(edit->text);
    cursor = edit->end;
  }
  if (cursor < original_size) {
    result.map.Append({output_size(), original_size - cursor, cursor, original_size, false});
    result.text.append(original.substr(cursor));
  }
  result.map.SetSizes(original_size, output_size());
  return result;
}

}  // namespace shaderport
