// vri: the command line. Every failure prints one line on stderr and exits
// non-zero; outputs are written atomically, so a failure leaves no file.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "commands.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"
#include "vri/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"vri: volume rendering with measurable accuracy"};
  app.require_subcommand(1);
  // Prints "vri 0.2.0" and exits 0 (before the subcommand is required).
  app.set_version_flag("--version", std::string("vri ") + vri::kVersion, "Print the version and exit");
  vri::cli::Runner render = vri::cli::add_render_command(app);
  vri::cli::Runner compare = vri::cli::add_compare_command(app);
  vri::cli::Runner table = vri::cli::add_table_command(app);
  vri::cli::Runner ray = vri::cli::add_ray_command(app);
  vri::cli::Runner view = vri::cli::add_view_command(app);
  vri::cli::Runner info = vri::cli::add_info_command(app);
  vri::cli::Runner turntable = vri::cli::add_turntable_command(app);
  vri::cli::Runner camera = vri::cli::add_camera_command(app);
  vri::cli::Runner devices = vri::cli::add_devices_command(app);
  // Global, accepted after the subcommand too (fallthrough).
  std::string max_memory;
  app.add_option("--max-memory", max_memory,
                 "Memory budget for volumes, meshes and tables: bytes or 512M, 4G, ... (default: 75% of RAM)");
  for (CLI::App* sub : app.get_subcommands({})) sub->fallthrough();
  try {
    app.parse(argc, argv);
    if (!max_memory.empty()) {
      const auto bytes = vri::parse_byte_size(max_memory);
      if (!bytes) {
        std::cerr << "vri: error: --max-memory expects a size such as 1073741824, 512M or 4G, got '" << max_memory
                  << "'\n";
        return 2;
      }
      vri::set_memory_limit(*bytes);
    }
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    // Subcommand help comes through here too.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "vri: error: " << vri::message_line(e.what()) << " (see vri --help)\n";
    return 2;
  }
  vri::remove_temporaries_on_signal();
  try {
    // Every file of the command is renamed into place only once it succeeded.
    vri::OutputTransaction outputs;
    const vri::cli::Runner& run = app.got_subcommand("render")    ? render
                                  : app.got_subcommand("compare") ? compare
                                  : app.got_subcommand("table")   ? table
                                  : app.got_subcommand("view")    ? view
                                  : app.got_subcommand("info")    ? info
                                  : app.got_subcommand("turntable") ? turntable
                                  : app.got_subcommand("camera")    ? camera
                                  : app.got_subcommand("devices")   ? devices
                                                                  : ray;
    const int code = run();
    if (code == 0) outputs.commit();
    return code;
  } catch (const vri::Error& e) {
    std::cerr << "vri: error: " << vri::message_line(e.what()) << "\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "vri: error: out of memory\n";
  } catch (const std::exception& e) {
    std::cerr << "vri: error: " << vri::message_line(e.what()) << "\n";
  }
  return 1;
}
