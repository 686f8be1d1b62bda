#pragma once

namespace mechanist {

/// The viewer page (viewer_template.cpp): HTML, style and the page's own script, with the
/// markers @TITLE@, @THREE@ (three.min.js), @ORBIT@ (OrbitControls.js) and @DATA@ (the
/// mechanism as JSON) that ViewerHtml fills.
extern const char* const kViewerTemplate;

}  // namespace mechanist
