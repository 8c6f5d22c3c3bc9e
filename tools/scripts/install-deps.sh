#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, if missing.
#   tools/scripts/install-deps.sh            compilers for `make test` (g++, clang)
#   tools/scripts/install-deps.sh window     + GLFW, Xvfb and xdotool for the window test
#   tools/scripts/install-deps.sh cross      + cross compilers, qemu, Cortex-M toolchain
#   tools/scripts/install-deps.sh oracle     + LinuxCNC's stand-alone interpreter rs274 (oracle-check.sh --rs274)
#   tools/scripts/install-deps.sh browser    + Chromium and its fonts for the sheet's browser test (sheet-test.sh)
#   tools/scripts/install-deps.sh web        + clang's wasm32 target (wasm-ld, wasi-libc, libc++, builtins) for
#                                              `make web`, and Chromium for its browser test (web-test.sh)
# Never installs g++-multilib: it removes the cross compilers (g++-12-multilib does not).
set -eu
pkgs="g++ clang make"
for extra in "$@"; do
  case $extra in
    window) pkgs="$pkgs libglfw3-dev pkg-config xvfb x11-apps xdotool imagemagick";;
    cross) pkgs="$pkgs g++-12-multilib g++-arm-linux-gnueabihf g++-aarch64-linux-gnu g++-powerpc-linux-gnu
                 g++-s390x-linux-gnu g++-mips-linux-gnu qemu-user gcc-arm-none-eabi libstdc++-arm-none-eabi-newlib
                 libnewlib-arm-none-eabi qemu-system-arm";;
    fuzz) pkgs="$pkgs libclang-rt-14-dev";;
    oracle) pkgs="$pkgs linuxcnc-uspace";;
    browser) pkgs="$pkgs chromium fonts-dejavu-core python3";;
    web) pkgs="$pkgs lld wasi-libc libc++-14-dev-wasm32 libclang-rt-14-dev-wasm32 chromium python3";;
    *) echo "install-deps.sh: unknown set '$extra'" >&2; exit 2;;
  esac
done
missing=$(for p in $pkgs; do dpkg -s "$p" >/dev/null 2>&1 || echo "$p"; done)
[ -z "$missing" ] && exit 0
SUDO=; [ "$(id -u)" = 0 ] || SUDO=sudo
echo "install-deps.sh: installing" $missing
$SUDO apt-get update -qq
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
