#pragma once
// The frame loop of `throng view`: window, swapchain, crowd, panel and input, until the window
// closes or --frames have been shown.
#include "view_options.h"

namespace throng::tools {

// Everything that needs neither a display nor a GPU; throws Error on the first problem (the
// same messages as `throng render` for the scene options).
void checkViewOptions(ViewOptions& options);

void runView(ViewOptions& options);

}  // namespace throng::tools
