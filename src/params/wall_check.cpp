#include "params/wall_check.hpp"

#include <fmt/format.h>

#include <string>

namespace puddle::params {

namespace {

// Where the value of `id` came from, as a message's prefix.
std::string origin(const Params& params, const Config& config, ParamId id, int value) {
    const std::string_view name = decl(id).name;
    switch (params.source(id)) {
        case ParamSource::Config:
            for (const ConfigEntry& e : config.entries)
                if (e.id == id) return fmt::format("config: {}:{}", config.path, e.line);
            break;
        case ParamSource::CommandLine:
            return fmt::format("--set {}={}", name, value);
        default:
            break;
    }
    return fmt::format("wall: {} from the {}", name, source_name(params.source(id)));
}

Result<void> check_position(const Params& params, const Config& config, ParamId position, ParamId count) {
    const int p = std::get<int>(params.at(position)), n = std::get<int>(params.at(count));
    if (p < n) return {};
    // The wall's size set elsewhere than the position (the config's columns, a --set column): name both,
    // so the person fixes the one that is wrong.
    const ParamSource count_source = params.source(count);
    const std::string count_origin =
        count_source != params.source(position) && count_source != ParamSource::Default
            ? fmt::format(", from {}", origin(params, config, count, n))
            : std::string();
    return make_error(ExitCode::Config, "{}: {} = {} is out of range: allowed 0 to {} (0-based; {} = {}{})",
                      origin(params, config, position, p), decl(position).name, p, n - 1, decl(count).name, n,
                      count_origin);
}

}  // namespace

Result<void> check_wall(const Params& params, const Config& config) {
    if (auto r = check_position(params, config, ParamId::wall_column, ParamId::wall_columns); !r) return r;
    return check_position(params, config, ParamId::wall_row, ParamId::wall_rows);
}

}  // namespace puddle::params
