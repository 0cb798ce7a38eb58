# Cross-build for 64-bit Arm Linux with Debian's g++-aarch64-linux-gnu and
# the arm64 (multiarch) dev packages; the tests run under qemu-user
# (scripts/cross_aarch64.sh, docs/PORTABILITY.md).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# Debian multiarch: the arm64 libraries and their CMake packages live in
# /usr/lib/aarch64-linux-gnu, header-only packages in /usr/share.
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
# try_run, gtest_discover_tests and ctest run target programs through this.
# -L /: the arm64 loader and libc of Debian multiarch (libc6:arm64, which the
# :arm64 dev packages pull in), beside the arm64 libraries the build links.
# Not the cross toolchain's copy in /usr/aarch64-linux-gnu: with it, the
# first thread a program starts hangs (qemu 7.2, glibc 2.36).
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /)
