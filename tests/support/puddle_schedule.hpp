#pragma once
// What the puddle plugin registers (systems/puddle/puddle_plugin.hpp), line by line as Schedule::describe()
// says it: the plugin's own test pins it, and the engine test pins the binary's whole frame around it.
// A change of order, of a run condition or of what a system reads and writes shows here first; update it
// on purpose.

#include <string>
#include <vector>

namespace puddle::test {

inline const std::vector<std::string> puddle_plugin_schedule = {
    "input/wall steps if wall.clock is realtime (reads WallClock, OutputPower, ShownLook, Params; writes "
    "WallSteps, FrameClock)",
    "input/frame clock if wall.clock is frame (reads FrameTime, Params; writes FrameClock)",
    "input/hold steps while off (reads OutputPower; writes FrameClock)",
    "input/wave rebuild (reads Params; writes Device, WaveField, Surface)",
    "input/environment reload (reads Params; writes Device, Environment, Ground, EnvironmentReload)",
    "input/look switch (reads Params, Looks; writes Device, ShownLook)",
    "input/camera feed (reads Params, FrameTime; writes CameraFeed, Device, CameraEnvironment)",
    "simulate/begin step (writes FrameClock)",
    "simulate/drops if the wave field is in use (the world; reads Params, FrameClock; writes DropSlots, "
    "LiveDrops)",
    "simulate/wave if the wave field is in use (reads Params, FrameClock, LiveDrops; writes Device, "
    "WaveField)",
    "render/surface if the wave field is in use and output on (reads WaveField; writes Device, Surface)",
    "render/camera environment if output on (reads Params, Environment; writes Device, CameraEnvironment)",
    "render/cloud drift if output on (reads Params, FrameClock; writes Clouds)",
    "render/analytic ripples if drops are analytic and output on (reads Params, FrameClock; writes Device, "
    "AnalyticRipples, "
    "Surface)",
    "render/grid drops if drops are grid and output on (reads Params, FrameClock; writes Device, GridDrops, "
    "Surface)",
    "render/puddle if look is puddle and output on (reads Params, Surface, Environment, Ground, Clouds, "
    "RenderTarget, CameraEnvironment; writes Device, PuddleRenderer)",
    "render/ocean if look is ocean and output on (reads Params, FrameClock, RenderTarget; writes Device, "
    "OceanRenderer)",
    "render/street if look is street and output on (reads Params, FrameClock, RenderTarget; writes Device, "
    "StreetRenderer)",
    "render/window if look is window and output on (reads Params, FrameClock, RenderTarget; writes Device, "
    "WindowRenderer)",
    "render/rain overlay if the rain overlay is on and output on (reads Params, FrameClock, RenderTarget; "
    "writes Device, "
    "RainOverlay)",
};

}  // namespace puddle::test
