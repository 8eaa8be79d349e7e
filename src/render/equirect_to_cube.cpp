#include "render/equirect_to_cube.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstddef>
#include <span>
#include <thread>

#include "render/banded_upload.hpp"

namespace puddle::render {
Result<gpu::Texture> create_environment_cube(gpu::Device& device, gpu::TextureFormat format, int face_size,
                                             int smallest_face_size) {
    auto make = [&](int size) {
        return device.create_texture({.label = "environment",
                                      .kind = gpu::TextureKind::Cube,
                                      .format = format,
                                      .width = size,
                                      .height = size,
                                      .mip_levels = gpu::full_mip_count(size),
                                      .render_target = true});
    };
    auto cube = make(face_size);
    if (cube || cube.error().code != ExitCode::GpuMemory) return cube;
    const Error first = cube.error();
    int size = face_size;
    while (size / 2 >= std::max(smallest_face_size, 1)) {
        size /= 2;
        auto smaller = make(size);
        if (smaller) {
            spdlog::warn("{}; using {}x{} faces instead", first.message, size, size);
            return smaller;
        }
        if (smaller.error().code != ExitCode::GpuMemory) return smaller;
    }
    if (size == face_size) return first;
    return Error{fmt::format("{}; faces down to {}x{} did not fit either", first.message, size, size),
                 first.code};
}

int auto_face_size(int panorama_width, int max_cube_size) {
    return std::clamp(panorama_width / 4, 1, std::min(1024, max_cube_size));
}

std::vector<assets::Image> panorama_mip_chain(assets::Image panorama, int max_texture_size,
                                              std::stop_token stop) {
    const int width = panorama.width, height = panorama.height;
    while (panorama.width > max_texture_size && !stop.stop_requested()) panorama = assets::halve(panorama);
    if (panorama.width != width)
        spdlog::info("environment: panorama shrunk from {}x{} to {}x{} (the GPU's largest texture is {})",
                     width, height, panorama.width, panorama.height, max_texture_size);
    std::vector<assets::Image> levels;
    const bool hdr = panorama.format == assets::PixelFormat::RGBA32F;
    const int count = hdr ? gpu::full_mip_count(panorama.width) : 1;
    levels.reserve(static_cast<std::size_t>(count));
    levels.push_back(std::move(panorama));
    while (static_cast<int>(levels.size()) < count && !stop.stop_requested())
        levels.push_back(assets::halve(levels.back()));
    return levels;
}

EquirectToCube::EquirectToCube(std::vector<assets::Image> levels, int face_size, gpu::TextureFormat format,
                               bool rgbm, int smallest_face_size)
    : levels_(std::move(levels)),
      face_size_(face_size),
      smallest_face_size_(smallest_face_size),
      format_(format),
      rgbm_(rgbm) {
    panorama_width_ = levels_.front().width;
    panorama_height_ = levels_.front().height;
    panorama_mips_ = gpu::full_mip_count(panorama_width_);
}

Result<bool> EquirectToCube::step(gpu::Device& device, long texel_budget, EquirectPipelines& pipelines) {
    switch (phase_) {
        case Phase::Upload: {
            if (!panorama_) {  // a step of its own: the driver may clear a large texture's memory
                const bool hdr = levels_.front().format == assets::PixelFormat::RGBA32F;
                auto made = device.create_texture(
                    {.label = "environment panorama",
                     .format = hdr ? gpu::TextureFormat::RGBA16F : gpu::TextureFormat::SRGB8_A8,
                     .width = panorama_width_,
                     .height = panorama_height_,
                     .mip_levels = panorama_mips_});
                if (!made) return made.error();
                panorama_ = std::move(made).value();
                return false;
            }
            assets::Image& level = levels_[uploaded_];
            if (!upload_next_band(panorama_, level, static_cast<int>(uploaded_), 0, upload_row_,
                                  texel_budget))
                return false;
            level = {};  // the GPU has it now: a large panorama's memory goes back at once
            upload_row_ = 0;
            if (++uploaded_ == levels_.size())
                phase_ = static_cast<int>(uploaded_) < panorama_mips_ ? Phase::Mipmaps : Phase::Pipeline;
            return false;
        }
        case Phase::Mipmaps:
            panorama_.generate_mipmaps();
            phase_ = Phase::Pipeline;
            return false;
        case Phase::Pipeline: {
            levels_.clear();
            auto built = pipelines.poll(device, rgbm_ ? CubeEncoding::rgbm : CubeEncoding::plain, [this] {
                std::vector<std::string> defines;
                if (rgbm_) defines.emplace_back("OUTPUT_RGBM");
                return gpu::PipelineDesc{.label = "equirect to cube",
                                         .fragment = "equirect_to_cube.frag",
                                         .defines = defines,
                                         .textures = {"u_panorama"}};
            });
            if (!built) return built.error();
            if (!*built) return false;  // still building, off the frame thread
            pipeline_ = &(*built)->pipeline;
            sampler_ = device.create_sampler(
                {.label = "environment panorama", .mipmaps = true, .wrap = gpu::Wrap::Repeat});
            phase_ = Phase::Cube;
            return false;
        }
        case Phase::Cube: {
            auto made = create_environment_cube(device, format_, face_size_, smallest_face_size_);
            if (!made) return made.error();
            cube_ = std::move(made).value();
            face_size_ = cube_.width();  // smaller where the asked size did not fit
            phase_ = Phase::Render;
            return false;
        }
        case Phase::Render: {
            // Every level from the panorama itself, filtered as wide as its texels: RGBM texels cannot be
            // averaged by the driver's mipmap generation (a bright window next to a dark wall would lose
            // most of its light). A large face goes in bands of rows, one band a step.
            const int size = std::max(1, face_size_ >> level_);
            const int rows =
                static_cast<int>(std::clamp(texel_budget / size, 1L, static_cast<long>(size - row_)));
            const bool whole = row_ == 0 && rows == size;
            auto pass = device.begin_pass(
                {.label = "equirect to cube",
                 .target = {.texture = &cube_, .size = {size, size}, .face = face_, .level = level_},
                 .load = whole ? gpu::LoadOp::DontCare : gpu::LoadOp::Load,
                 .rows = {row_, whole ? 0 : rows}});
            pass.set_pipeline(*pipeline_)
                .set_texture(0, panorama_, sampler_)
                .set("u_face", face_)
                .set("u_face_size", static_cast<float>(size))
                .set("u_panorama_size", glm::vec2(panorama_width_, panorama_height_))
                .set("u_max_lod", static_cast<float>(panorama_mips_ - 1));
            pass.draw_fullscreen();
            pass.end();
            if ((row_ += rows) < size) return false;
            row_ = 0;
            if (++face_ < 6) return false;
            face_ = 0;
            if (++level_ < cube_.desc().mip_levels) return false;
            phase_ = Phase::Done;
            panorama_ = {};
            return true;
        }
        case Phase::Done:
            return true;
    }
    return true;
}

Result<gpu::Texture> equirect_to_cube(gpu::Device& device, const assets::Image& panorama, int face_size,
                                      gpu::TextureFormat format, bool rgbm, int smallest_face_size) {
    EquirectToCube conversion(panorama_mip_chain(panorama, device.caps().max_texture_size), face_size, format,
                              rgbm, smallest_face_size);
    EquirectPipelines pipelines;
    for (;;) {
        auto done = conversion.step(device, static_cast<long>(face_size) * face_size, pipelines);
        if (!done) return done.error();
        if (*done) return conversion.take_cube();
        std::this_thread::yield();  // while the pipeline builds on the compiler's thread
    }
}

}  // namespace puddle::render
