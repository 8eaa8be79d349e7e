#pragma once
// The pure part of backend selection, separate from create_display() so it can be unit-tested without
// any device: given what was asked for, what the KMS probe found and $DISPLAY, which backend and why.

#include <string>
#include <vector>

#include "platform/display.hpp"

namespace puddle::platform {

struct BackendChoice {
    BackendKind kind = BackendKind::Headless;
    std::string reason;  // one clause for the start-up log: "no /dev/dri/card* devices; DISPLAY not set"
    // Auto only: what to try, in order, when `kind` fails to start. Explicit requests never fall back.
    std::vector<BackendKind> fallbacks;
};

// `requested` other than Auto is returned as is. `display_env` is getenv("DISPLAY"), null when unset.
BackendChoice choose_backend(BackendKind requested, const KmsProbe& kms, const char* display_env);

}  // namespace puddle::platform
