#include "ffmpeg_library.hpp"

#if VRI_HAVE_FFMPEG
#include <dlfcn.h>

#include <mutex>
#include <string>

#include "vri/error.hpp"

namespace vri::cli {

namespace {

#define VRI_STRING(x) #x
#define VRI_SONAME(lib, major) "lib" lib ".so." VRI_STRING(major)

FFmpeg load() {
  // libavformat brings libavcodec and libavutil; each is opened by the soname
  // of the headers vri was built with.
  const char* sonames[] = {VRI_SONAME("avutil", LIBAVUTIL_VERSION_MAJOR), VRI_SONAME("avcodec", LIBAVCODEC_VERSION_MAJOR),
                           VRI_SONAME("avformat", LIBAVFORMAT_VERSION_MAJOR),
                           VRI_SONAME("swscale", LIBSWSCALE_VERSION_MAJOR)};
  void* handles[4];
  for (int i = 0; i < 4; ++i) {
    handles[i] = dlopen(sonames[i], RTLD_NOW | RTLD_LOCAL);
    if (!handles[i]) {
      const char* why = dlerror();
      throw Error(std::string("video: cannot load FFmpeg's ") + sonames[i] + " (" + (why ? why : "?") +
                  "); install libavformat59, libavcodec59 and libswscale6 or write the frames to a folder");
    }
  }
  FFmpeg f;
  auto find = [&](const char* name) -> void* {
    for (void* h : handles)
      if (void* p = dlsym(h, name)) return p;
    throw Error(std::string("video: FFmpeg's libraries lack ") + name);
  };
#define VRI_FFMPEG_LOAD(name) f.name = reinterpret_cast<decltype(f.name)>(find(#name));
  VRI_FFMPEG_FUNCTIONS(VRI_FFMPEG_LOAD)
#undef VRI_FFMPEG_LOAD
  return f;  // the libraries stay loaded for the process
}

}  // namespace

const FFmpeg& ffmpeg() {
  static const FFmpeg functions = load();  // a failed load throws and is retried next time
  return functions;
}

}  // namespace vri::cli
#endif
