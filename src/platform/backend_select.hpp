#pragma once
// The pure part of backend selection, separate from create_display() so it can be unit-tested without
// any device: given what was asked for, what the KMS probe found and $DISPLAY, which backend and why.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "platform/display.hpp"

namespace puddle::platform {

// The one table of backends: the CLI's choices and help, the names in logs and the factories all come from
// it. "auto" is not a backend but the choice among them (choose_backend).
struct BackendInfo {
    BackendKind kind;
    std::string_view name;     // what --backend takes
    std::string_view summary;  // for --help: where the frames go
    Result<std::unique_ptr<Display>> (*create)(const DisplayOptions& options);
};
std::span<const BackendInfo> display_backends();
// "auto" or a backend's name; nullopt for anything else.
std::optional<BackendKind> backend_from_name(std::string_view name);

struct BackendChoice {
    BackendKind kind = BackendKind::Headless;
    std::string reason;  // one clause for the start-up log: "no /dev/dri/card* devices; DISPLAY not set"
    // Auto only: what to try, in order, when `kind` fails to start. Explicit requests never fall back.
    std::vector<BackendKind> fallbacks;
};

// `requested` other than Auto is returned as is. `display_env` is getenv("DISPLAY"), null when unset.
BackendChoice choose_backend(BackendKind requested, const KmsProbe& kms, const char* display_env);

}  // namespace puddle::platform
