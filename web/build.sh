#!/usr/bin/env bash
# Builds the lab for the browser into dist/ on a machine like the project's, whose
# rustup has no wasm32-unknown-unknown standard library and cannot download one: Debian's Rust
# toolchain (rustc-web, cargo-web, rust-web-src, lld) builds std for wasm32 itself. A user
# with rustup does `rustup target add wasm32-unknown-unknown` and `trunk build --release`.
#
#   web/build.sh            writes dist/index.html, dist/ltc_lab_web.js, dist/ltc_lab_web_bg.wasm
#   web/build.sh --test     the same from the `web-test` profile (Cargo.toml): what the browser
#                           test opens, built in a fraction of the time, not size-optimized
#
# The build has its own target directory (target/web) so that the two toolchains do not
# rebuild each other's files; wasm-bindgen-cli is installed into target/web-tools at the
# version Cargo.lock pins for the wasm-bindgen crate (the two must match).
set -euo pipefail
cd "$(dirname "$0")/.."
profile=web
case "${1:-}" in
    "") ;;
    --test) profile=web-test ;;
    *) echo "web/build.sh: unknown argument $1 (--test or nothing)" >&2; exit 2 ;;
esac

if [ ! -x /usr/bin/wasm-ld ] || [ ! -d /usr/lib/rustlib/src/rust/library ]; then
    if [ "$(id -u)" = 0 ]; then
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq rustc-web cargo-web rust-web-src lld binaryen > /dev/null
    else
        echo "web/build.sh: needs Debian's rustc-web cargo-web rust-web-src lld (apt-get install as root)" >&2
        exit 1
    fi
fi

version=$(grep -A1 '^name = "wasm-bindgen"$' Cargo.lock | sed -n 's/^version = "\(.*\)"$/\1/p')
tools=target/web-tools
if ! "$tools/bin/wasm-bindgen" --version 2>/dev/null | grep -q " $version\$"; then
    # Not --locked: the registry here lacks one of the CLI's pinned dependencies. --debug: a
    # clean unoptimized build takes 2.0 min here against some 4.5 optimized, and the tool
    # writes the same bytes (.wasm and .js compared here) in 16 s instead of 3.
    cargo install -q --debug wasm-bindgen-cli --version "=$version" --root "$tools"
fi

start=$(date +%s)
PATH=/usr/bin:$PATH RUSTC_BOOTSTRAP=1 CARGO_TARGET_DIR=target/web \
RUSTFLAGS='-C linker=/usr/bin/wasm-ld --cfg getrandom_backend="wasm_js"' \
    /usr/bin/cargo build -q --locked --profile "$profile" -p ltc-lab-web \
    -Z build-std=std,panic_abort --target wasm32-unknown-unknown

rm -rf dist
mkdir -p dist
wasm=target/web/wasm32-unknown-unknown/$profile/ltc_lab_web.wasm
# wasm-opt (Debian's binaryen) before wasm-bindgen, not after: run on wasm-bindgen's output,
# binaryen 108 broke its function table (a WebAssembly.Table.set TypeError in Chromium). The
# features are those Rust's wasm32 target emits.
# About a minute on 2 cores: skipped where the optimized file is newer than the build's.
if [ "$profile" = web-test ]; then
    : # the test's bundle: its size is not what is measured
elif command -v wasm-opt > /dev/null; then
    optimized=target/web/ltc_lab_web.wasm
    if [ ! "$optimized" -nt "$wasm" ]; then
        wasm-opt -Os --enable-reference-types --enable-bulk-memory \
            --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals \
            --enable-multivalue "$wasm" -o "$optimized"
    fi
    wasm=$optimized
else
    echo "web/build.sh: no wasm-opt (apt-get install binaryen): the bundle is not size-optimized" >&2
fi
"$tools/bin/wasm-bindgen" --target web --no-typescript --out-dir dist "$wasm"
python3 - <<'PY'
import pathlib
page = pathlib.Path("web/index.html").read_text()
loader = """<script type="module">
  import init from "./ltc_lab_web.js";
  init().catch((e) => {
    const status = document.getElementById("status");
    status.style.display = "";
    status.textContent = "The LTC lab could not load: " + e;
  });
</script>"""
page = page.replace("<!-- loader -->", loader)
# Trunk's own link is for Trunk only.
page = "\n".join(l for l in page.splitlines() if "data-trunk" not in l) + "\n"
pathlib.Path("dist/index.html").write_text(page)
PY
wasm=dist/ltc_lab_web_bg.wasm
echo "web/build.sh: dist/ ($profile profile) in $(( $(date +%s) - start )) s; $(stat -c %s $wasm) bytes of wasm, $(gzip -9 -c $wasm | wc -c) gzipped"
