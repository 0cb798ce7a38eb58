#pragma once
// The subcommands of the `vri` program (SPEC §10). Each registers its options
// on the CLI11 app and runs when selected; errors are thrown as vri::Error.
#include <CLI/CLI.hpp>

#include <functional>

namespace vri::cli {

using Runner = std::function<int()>;

Runner add_render_command(CLI::App& app);
Runner add_compare_command(CLI::App& app);
Runner add_table_command(CLI::App& app);
Runner add_ray_command(CLI::App& app);
Runner add_view_command(CLI::App& app);
Runner add_info_command(CLI::App& app);
Runner add_turntable_command(CLI::App& app);
Runner add_camera_command(CLI::App& app);
Runner add_devices_command(CLI::App& app);

}  // namespace vri::cli
