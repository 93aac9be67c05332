// The one page `tracer view` serves: the frame, its figures and the camera controls.
#pragma once

namespace tracer {

const char* view_page_html();

}  // namespace tracer
