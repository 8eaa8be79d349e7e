#pragma once
// The pipelines of one pass, keyed by the variant they are built for (Bevy's specialised pipelines): each
// key is built the first time it is asked for, so variants, scenes and models nobody selects cost no
// shader compile, and a look switched on at run time still works. This is the one place where "build
// once, log a failure once" is written:
// - at start-up `ensure` builds at once (a broken shader stops start-up with its message);
// - in the frame loop `request` has it built off the frame thread (Device::request_pipeline) and says
//   when it is ready, so the old picture stays on screen meanwhile;
// - a failed build logs one line, once, and that key is never tried again (a shader that failed to
//   compile fails the same way every frame); `poll` returns that error instead, for passes that report it
//   in their own words;
// - `request_or_last` gives the pipeline of the key returned last while a new key builds or after it
//   failed, so a knob that needs a new variant switches the picture in the frame it is ready.
// Keys map to a fixed array of slots through a dense index: nothing is allocated in the steady state.

#include <spdlog/spdlog.h>

#include <array>
#include <cstddef>
#include <string_view>

#include "gpu/device.hpp"
#include "render/param_uniforms.hpp"
#include "util/result.hpp"

namespace puddle::render {

// A pipeline as a pass sets it: the program and the parameters its shader reads (render/param_uniforms.hpp).
struct BuiltPipeline {
    gpu::Pipeline pipeline;
    ParamBinding params;
};

// The key of a pass that has one pipeline only.
struct SinglePipeline {};
constexpr std::size_t single_pipeline_index(const SinglePipeline&) {
    return 0;
}

// The dense index of an enum key whose values are 0, 1, ... Count - 1.
template <class Enum>
constexpr std::size_t enum_index(const Enum& e) {
    return static_cast<std::size_t>(e);
}

// Key: what selects a variant. Count: how many keys there are. IndexOf: a key's slot, in [0, Count).
template <class Key, std::size_t Count, std::size_t (*IndexOf)(const Key&)>
class PipelineCache {
public:
    // `failure_note`, when not empty, ends the one line a failed build logs: "(keeping the look shown)".
    PipelineCache() = default;
    explicit PipelineCache(std::string_view failure_note) : failure_note_(failure_note) {}

    // Start-up: builds `key` now, waiting for the compile. make_desc() (a gpu::PipelineDesc) is called only
    // when a build is due. Errors are create_pipeline's and bind_params'; they are returned, not logged,
    // and the key is not tried again ("gpu: pipeline failed to build before").
    template <class MakeDesc>
    Result<void> ensure(gpu::Device& device, const Key& key, MakeDesc&& make_desc) {
        Slot& slot = slot_of(key);
        if (!ready(slot)) {
            if (slot.failed) return make_error(ExitCode::Runtime, "gpu: pipeline failed to build before");
            slot.building = {};
            if (auto kept = keep(slot, device.create_pipeline(make_desc())); !kept) return kept;
        }
        if (last_ == Count) last_ = IndexOf(key);  // what request_or_last shows until a frame asks
        return {};
    }

    // The frame loop: the pipeline for `key` once it is built, else null; starts (or checks on) a build
    // that does not block. A failure is logged once, then null for good.
    template <class MakeDesc>
    const BuiltPipeline* request(gpu::Device& device, const Key& key, MakeDesc&& make_desc) {
        if (slot_of(key).failed) return nullptr;
        auto polled = poll(device, key, std::forward<MakeDesc>(make_desc));
        if (!polled) {
            log_failure(polled.error());
            return nullptr;
        }
        return *polled;
    }

    // As request, for a caller that reports a failure in its own words: the error is returned, not logged,
    // the one time the build fails, and "failed to build before" at every later call. Null while building.
    template <class MakeDesc>
    Result<const BuiltPipeline*> poll(gpu::Device& device, const Key& key, MakeDesc&& make_desc) {
        Slot& slot = slot_of(key);
        if (ready(slot)) return &slot.built;
        if (slot.failed) return make_error(ExitCode::Runtime, "gpu: pipeline failed to build before");
        if (!slot.building.active()) slot.building = device.request_pipeline(make_desc());
        auto built = device.take_pipeline(slot.building);
        if (!built) return static_cast<const BuiltPipeline*>(nullptr);  // the worker is still on it
        if (auto kept = keep(slot, std::move(*built)); !kept) return kept.error();
        return &slot.built;
    }

    // As request, but while `key` builds, or after it failed, the pipeline this (or ensure at start-up)
    // returned last: the last good picture stays. Null only when none was ever ready.
    template <class MakeDesc>
    const BuiltPipeline* request_or_last(gpu::Device& device, const Key& key, MakeDesc&& make_desc) {
        if (const BuiltPipeline* p = request(device, key, std::forward<MakeDesc>(make_desc))) {
            last_ = IndexOf(key);
            return p;
        }
        return last_ == Count ? nullptr : &slots_[last_].built;
    }

    // The pipeline for `key` if it is built; never builds (for passes that only draw).
    const BuiltPipeline* find(const Key& key) const {
        const Slot& slot = slots_[IndexOf(key)];
        return ready(slot) ? &slot.built : nullptr;
    }
    bool failed(const Key& key) const { return slots_[IndexOf(key)].failed; }

    // Something `key`'s pass needs besides its shader could not be made (a data texture): treated as a
    // failed build, logged once now and never tried again.
    void fail(const Key& key, const Error& error) {
        Slot& slot = slot_of(key);
        if (slot.failed) return;
        slot = {};
        slot.failed = true;
        if (last_ == IndexOf(key)) last_ = Count;
        log_failure(error);
    }

private:
    struct Slot {
        BuiltPipeline built;
        gpu::PipelineRequest building;  // a build in flight
        bool failed = false;
    };

    static bool ready(const Slot& slot) { return slot.built.pipeline.id() != 0; }
    Slot& slot_of(const Key& key) { return slots_[IndexOf(key)]; }

    Result<void> keep(Slot& slot, Result<gpu::Pipeline> built) {
        auto binding = built ? bind_params(*built) : Result<ParamBinding>(built.error());
        if (!binding) {
            slot.failed = true;
            return binding.error();
        }
        slot.built = {std::move(built).value(), std::move(binding).value()};
        return {};
    }

    void log_failure(const Error& error) const {
        if (failure_note_.empty())
            spdlog::error("{}", error.message);
        else
            spdlog::error("{} ({})", error.message, failure_note_);
    }

    std::array<Slot, Count> slots_{};
    std::size_t last_ = Count;  // the slot request_or_last returned last; Count: none yet
    std::string_view failure_note_;
};

// The cache of a pass with one pipeline.
using SinglePipelineCache = PipelineCache<SinglePipeline, 1, single_pipeline_index>;

}  // namespace puddle::render
