// vri devices (SPEC §11): the Vulkan devices `--backend vulkan` can use, one
// a line with the index VRI_VULKAN_DEVICE picks it by; "no Vulkan device"
// (exit 1) when there is none, so a script can test for a GPU.
#include <iostream>
#include <string>

#include "commands.hpp"
#include "vri/render.hpp"

namespace vri::cli {

Runner add_devices_command(CLI::App& app) {
  app.add_subcommand("devices", "List the Vulkan devices for --backend vulkan");
  return [] {
    const std::vector<std::string> devices = list_vulkan_devices();
    if (devices.empty()) {
      std::cerr << "vri: no Vulkan device found (install mesa-vulkan-drivers for the CPU, or a GPU's driver)\n";
      return 1;
    }
    for (const std::string& d : devices) std::cout << d << "\n";
    return 0;
  };
}

}  // namespace vri::cli
