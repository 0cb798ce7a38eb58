#include "io/exr_output.hpp"

#include <string>

#include "vri/error.hpp"
#include "vri/io.hpp"

#if VRI_HAVE_OPENEXR
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#endif

namespace vri {

#if VRI_HAVE_OPENEXR
bool exr_supported() { return true; }

void write_exr(const std::filesystem::path& path, const Image& image) {
  const int W = image.width(), H = image.height();
  try {
    Imf::Header header(W, H);
    static const char* const kChannels[] = {"R", "G", "B", "A"};
    for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::StdOSStream memory;  // in memory first: the file appears whole or not at all
    {
      Imf::OutputFile file(memory, header);
      Imf::FrameBuffer frame;
      auto* base = reinterpret_cast<char*>(const_cast<float*>(image.data().data()));
      for (int c = 0; c < 4; ++c)
        frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                              std::size_t(W) * 4 * sizeof(float)));
      file.setFrameBuffer(frame);
      file.writePixels(H);
    }
    const std::string bytes = memory.str();
    write_file_atomically(path, std::as_bytes(std::span(bytes.data(), bytes.size())));
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error("cannot write '" + path.string() + "' as OpenEXR: " + e.what());
  }
}
#else
bool exr_supported() { return false; }

void write_exr(const std::filesystem::path& path, const Image&) {
  throw Error("cannot write '" + path.string() + "': this vri was built without OpenEXR (install libopenexr-dev)");
}
#endif

}  // namespace vri
