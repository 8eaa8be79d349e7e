#pragma once
// The look switch (input stage, after live tuning): when the parameters choose another scene or drop
// model, it has that look's pipelines built off the frame thread (its Looks entry's request) and moves
// ShownLook to it in the first frame they are all ready. Until then the old look stays on screen and the
// frame loop keeps its pace and the watchdog ping (no shader compile on the frame thread). A look whose
// pipeline fails to build is never switched to: its error is logged once and the old look stays, as with
// any bad live edit. The entries write their own looks' pipeline caches.

#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "systems/common/looks.hpp"
#include "systems/common/shown_look.hpp"

namespace puddle::systems {

void look_switch_system(gpu::Device& device, const params::Params& params, const Looks& looks,
                        ShownLook& shown);

}  // namespace puddle::systems
