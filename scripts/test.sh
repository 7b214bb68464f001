#!/usr/bin/env bash
# Runs every test of tfem from a fresh clone: installs the system packages
# the C/C++ tests need (Debian), then formatting, lints, the Rust and C/C++
# tests (cargo test runs the C/C++ programs too) and the CTest suite.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libeigen3-dev cmake g++ gfortran pkg-config)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

echo "== cargo fmt --check"
cargo fmt --all -- --check

echo "== cargo clippy --all-targets -- -D warnings"
cargo clippy --release --all-targets -- -D warnings

echo "== core without optional I/O (no default features)"
cargo build --release --lib --no-default-features
if nm -D --defined-only target/release/libtfem.so | grep -qi vtk; then
  echo "the core library links VTK output code without the vtu feature" >&2
  exit 1
fi

echo "== cargo test --release (Rust, C and C++ tests)"
cargo build --release --lib
cargo test --release

echo "== ctest"
cmake -S c_tests -B build/c_tests -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/c_tests -j 2 >/dev/null
ctest --test-dir build/c_tests --output-on-failure
