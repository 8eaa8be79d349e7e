#pragma once
// `puddle --check`: the one command a technician runs on a board. It looks at everything Puddle uses
// (the config, DRM/KMS screens, the GPU through EGL/GLES, GPIO chips and the configured knobs, V4L2
// cameras) and prints, for each, OK or what to fix. Missing hardware is reported, not an error: exit 0
// unless the config is invalid (2) or no GLES 3 context can be made (4).

#include <string>

namespace puddle::app {

struct CliOptions;

// Prints the report to stdout; returns the exit code.
int run_check(const CliOptions& options, const std::string& config_path);

}  // namespace puddle::app
