#pragma once
// The JavaScript and CSS report.html inlines, embedded at build time
// (core/report/CMakeLists.txt): Debian's three.js and dygraphs, and ours.
#include <string_view>

namespace unimap::report {

// Each asset's text.
struct ReportAssets {
  std::string_view three_js;           // three.js (libjs-three), defines THREE
  std::string_view orbit_controls_js;  // THREE.OrbitControls (libjs-three's examples)
  std::string_view dygraphs_js;        // Dygraph (libjs-dygraphs)
  std::string_view dygraphs_css;       // dygraphs' stylesheet
  std::string_view viewer_js;          // assets/viewer.js: the 3D view (UnimapViewer)
  std::string_view report_js;          // assets/report.js: builds the page from the embedded data
  std::string_view report_css;         // assets/report.css
};

// The assets compiled into this library.
const ReportAssets& EmbeddedAssets();

}  // namespace unimap::report
