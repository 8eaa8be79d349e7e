#include "assets/image_module.hpp"

#include <dlfcn.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

Result<const PuddleImageModule*> load() {
    const std::string path = image_module_path();
    // RTLD_LOCAL: OpenImageIO's symbols stay out of the global namespace. Never unloaded: OpenImageIO
    // keeps worker threads and static state for the life of the process.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        std::string why = dlerror();
        if (why.rfind(path + ": ", 0) == 0) why.erase(0, path.size() + 2);  // dlerror repeats the path
        return make_error(ExitCode::Asset,
                          "image module {}: {} (it reads image files; {} overrides its path)", path, why,
                          image_module_env);
    }
    auto entry = reinterpret_cast<PuddleImageModuleEntry>(dlsym(handle, PUDDLE_IMAGE_MODULE_ENTRY));
    if (entry == nullptr)
        return make_error(ExitCode::Asset, "image module {}: no {}(): not a puddle image module", path,
                          PUDDLE_IMAGE_MODULE_ENTRY);
    const PuddleImageModule* module = entry();
    if (module == nullptr || module->abi_version != PUDDLE_IMAGE_MODULE_ABI_VERSION)
        return make_error(ExitCode::Asset, "image module {}: interface version {}, this puddle needs {}",
                          path, module ? module->abi_version : 0, PUDDLE_IMAGE_MODULE_ABI_VERSION);
    spdlog::debug("image module: {}", path);
    return module;
}

}  // namespace

std::string image_module_path() {
    if (const char* env = std::getenv(image_module_env); env != nullptr && *env != '\0') return env;
    std::error_code ec;
    const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    const fs::path build_tree = exe_dir / "lib" / "puddle" / image_module_file;
    const fs::path installed = (exe_dir / ".." / "lib" / "puddle" / image_module_file).lexically_normal();
    return fs::exists(build_tree, ec) ? build_tree.string() : installed.string();
}

Result<const PuddleImageModule*> image_module() {
    static const Result<const PuddleImageModule*> loaded = load();  // thread-safe, once
    return loaded;
}

}  // namespace puddle::assets
