#pragma once
// `puddle --check`: the one command a technician runs on a board. It looks at everything Puddle uses
// (the config, the system clock's synchronisation, DRM/KMS screens, the GPU through EGL/GLES, GPIO chips
// and the configured knobs, V4L2 cameras) and prints, for each, OK or what to fix. Missing hardware is
// reported, not an error: exit 0 unless the config is invalid (2) or no GLES 3 context can be made (4).

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "gpu/capabilities.hpp"
#include "systems/clock/wall_clock.hpp"

namespace puddle::app {

struct CliOptions;

// Where the report looks for hardware and where it is written. The program (and the VM test) use the
// defaults; tests give folders of their own so that the report does not depend on the machine's /dev.
struct CheckSources {
    std::string dri_folder = "/dev/dri";  // DRM card nodes card0, card1, ... (platform::list_drm_cards)
    std::string video_folder = "/dev";    // V4L2 nodes video0, video1, ...
    std::FILE* out = stdout;
    // The kernel's view of the system clock (adjtimex); tests give a status of their own.
    std::function<systems::ClockSync()> clock_sync = systems::read_clock_sync;
};

// Writes the report; returns the exit code.
int run_check(const CliOptions& options, const std::string& config_path, const CheckSources& sources = {});

// One GPU feature Puddle uses, as the report's [GPU] section says it: its name, and when it is missing,
// ": missing; " and what Puddle does without it.
struct GpuFeatureLine {
    bool present = false;
    std::string text;
};
// The features in report order, from the context's capabilities; `dmabuf_import`: the EGL display has
// EGL_EXT_image_dma_buf_import.
std::vector<GpuFeatureLine> gpu_feature_lines(const gpu::Capabilities& caps, bool dmabuf_import);

}  // namespace puddle::app
