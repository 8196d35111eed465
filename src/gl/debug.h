// KHR_debug (core in GL 4.3): driver messages go to the log. Enabled for debug builds and --debug-gl.
#pragma once

namespace tidepool::gl {

// Installs the message callback (synchronous, so messages point at the call that caused them).
// Notifications are dropped; performance hints are logged at debug level; errors as errors.
void enableDebugOutput();

}  // namespace tidepool::gl
