#pragma once
// A second GL context that shares objects (programs, textures, buffers) with the frame thread's, for a
// worker thread: the pipeline compiler links shaders in it so the frame thread never waits for a
// compile (EGL 1.5 section 3.7.1 share_context; GLES 3.2 section 5, "Shared Objects and Multiple
// Contexts"). Made by the display backend, which owns the EGL display (platform/egl_context.cpp).

#include "util/result.hpp"

namespace puddle::gpu {

class WorkerContext {
public:
    virtual ~WorkerContext() = default;
    // Makes the context current, with no surface, on the calling thread (the worker); an error names the
    // EGL call and its error.
    virtual Result<void> make_current() = 0;
    // Makes no context current on the calling thread; the worker calls it before it ends.
    virtual void release() = 0;
};

}  // namespace puddle::gpu
