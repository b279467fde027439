// Byte-range edits on a text, and the source map that leads from the edited
// text back to the original, across several rounds of editing.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace shaderport {

// Replace original bytes [begin, end) with `text`; begin == end inserts.
struct Edit {
  uint32_t begin = 0;
  uint32_t end = 0;
  std::string text;
  friend bool operator==(const Edit&, const Edit&) = default;
};

// True when the two edits cannot both be applied: their ranges share a byte, or
// one inserts strictly inside the range the other replaces. Insertions at the
// same offset do not overlap (they are applied in the order given).
bool EditsOverlap(const Edit& a, const Edit& b);

// One run of output bytes: either copied from the original, or inserted text
// that stands in for original bytes [original_begin, original_end).
struct MapSegment {
  uint32_t output_begin = 0;
  uint32_t length = 0;
  uint32_t original_begin = 0;
  uint32_t original_end = 0;  // copied: original_begin + length
  bool inserted = false;
  friend bool operator==(const MapSegment&, const MapSegment&) = default;
};

// Maps offsets of an output text to offsets of the original it was made from.
class SourceMap {
 public:
  SourceMap() = default;
  static SourceMap Identity(uint32_t size);

  // Offset in the original of output byte `offset`. Inserted bytes map to the
  // start of what they replaced; `offset == OutputSize()` maps to the end.
  uint32_t ToOriginal(uint32_t offset) const;
  // The original range an output range stands for; an output range that
  // touches inserted text widens to the whole range the insertion replaced.
  std::pair<uint32_t, uint32_t> ToOriginalRange(uint32_t begin, uint32_t end) const;
  // True when the output bytes [begin, end) are an unchanged copy of original bytes.
  bool IsCopied(uint32_t begin, uint32_t end) const;

  uint32_t OutputSize() const { return output_size_; }
  uint32_t OriginalSize() const { return original_size_; }
  const std::vector<MapSegment>& Segments() const { return segments_; }

  // The map of applying `first` then `second`: output of `second` -> original of `first`.
  static SourceMap Compose(const SourceMap& first, const SourceMap& second);

  // Appends a segment, merging it with the previous one when they are contiguous.
  void Append(MapSegment segment);
  void SetSizes(uint32_t original_size, uint32_t output_size) {
    original_size_ = original_size;
    output_size_ = output_size;
  }

 private:
  const MapSegment* SegmentAt(uint32_t offset) const;

  std::vector<MapSegment> segments_;  // sorted by output_begin, covering the output
  uint32_t original_size_ = 0;
  uint32_t output_size_ = 0;
};

struct EditResult {
  std::string text;
  SourceMap map;  // text -> original
};

// Applies non-overlapping edits (any order; stable for insertions at one
// offset). nullopt when two edits overlap or an edit lies outside `original`:
// the caller decides which edit wins.
std::optional<EditResult> ApplyEdits(std::string_view original, std::span<const Edit> edits);

}  // namespace shaderport
