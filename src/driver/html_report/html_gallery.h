// The first screen of the HTML report: one tile per entry (thumbnail, status
// badge, file name) linking to the entry's details, and pure-CSS filters.
#pragma once

#include <string>
#include <string_view>

#include "driver/html_report/html_report.h"

namespace shaderport::driver {

// The one status a tile shows, the worst first: any step failed; else any step
// warned; else no picture was drawn; else it passes.
enum class EntryStatus { kFail, kWarn, kNotRendered, kPass };
EntryStatus StatusOfEntry(const ReportEntry& entry);
// The CSS class: "is-fail", "is-warn", "is-not-rendered", "is-pass".
const char* EntryStatusClass(EntryStatus status);
// The badge text: "fails", "warnings", "not rendered", "passes".
const char* EntryStatusLabel(EntryStatus status);

// The id of entry `index`'s details section ("shader-1", ...), the tiles' targets.
std::string EntryAnchor(size_t index);

// Rules for the tiles and for the filters, which hide tiles and details sections
// by status without a script (the page's policy forbids scripts).
extern const std::string_view kGalleryStyle;

// The filters' radio inputs: they must precede #gallery and #shaders as siblings
// for the `:checked ~` rules to reach them.
void AppendFilterInputs(std::string& out);

// `<section id="gallery">`: the filter labels with counts, then the tiles.
void AppendGallery(std::string& out, const HtmlReport& report);

}  // namespace shaderport::driver
