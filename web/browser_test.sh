#!/usr/bin/env bash
# The lab in a real browser (issue 21): builds dist/ (web/build.sh), serves it on 127.0.0.1
# and opens it in headless Chromium twice, on WebGL2 and on WebGPU (SwiftShader):
#   - no console message of a failure (a panic, an uncaught exception, a WGSL error, the
#     page's own "could not load" / "stopped") in either run;
#   - the page's loading message is gone (the lab started) in either run;
#   - on WebGL2, a screenshot of the page holds the lab (the WebGPU canvas is not composited
#     in headless Chromium here: its screenshots are black, so that run is read, not seen).
# Without Chromium it says so and stops with 0, unless LTC_LAB_REQUIRE_BROWSER=1 (.ci/run sets
# it), where a missing browser is a failure.
set -euo pipefail
cd "$(dirname "$0")/.."

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    if [ "${LTC_LAB_REQUIRE_BROWSER:-}" = 1 ]; then
        echo "web/browser_test.sh: FAILED: no Chromium and LTC_LAB_REQUIRE_BROWSER=1" >&2
        exit 1
    fi
    echo "web/browser_test.sh: SKIPPED: no Chromium here (apt-get install chromium); the browser checks did not run" >&2
    exit 0
fi

bash web/build.sh
out=$(mktemp -d)
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory dist > "$out/http.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do
    python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
    sleep 0.1
done
url="http://127.0.0.1:$port/"

# Runs Chromium on the page with `$@` and a virtual-time budget long enough for the lab's
# first frames; its console goes to $out/$name.log, the page's DOM to $out/$name.html.
open_page() {
    local name=$1
    shift
    "$browser" --headless=new --no-sandbox --disable-gpu-sandbox --enable-logging=stderr --v=0 \
        --window-size=1280,800 --virtual-time-budget=30000 "$@" --dump-dom "$url" \
        > "$out/$name.html" 2> "$out/$name.log"
}

# Console messages that mean a failure; the rest (SwiftShader's notices, eframe probing for a
# WebGPU adapter before it takes WebGL2) are not.
check_console() {
    local name=$1
    if grep 'CONSOLE' "$out/$name.log" \
        | grep -E -i 'panicked|uncaught|error while|could not load|stopped:|wgpu error|validation error' \
        > "$out/$name.errors"; then
        echo "web/browser_test.sh: FAILED: $name: console errors:" >&2
        cut -c1-400 "$out/$name.errors" >&2
        exit 1
    fi
    if ! grep -q '<div id="status" style="display:none">' "$out/$name.html"; then
        echo "web/browser_test.sh: FAILED: $name: the lab did not start; the page says:" >&2
        grep -o '<div id="status"[^<]*' "$out/$name.html" >&2 || true
        exit 1
    fi
}

open_page webgl2
check_console webgl2
"$browser" --headless=new --no-sandbox --window-size=1280,800 --virtual-time-budget=30000 \
    --screenshot="$out/webgl2.png" "$url" > /dev/null 2>&1
# A page with the lab on it: its panels, text and the shaded plane compress to far more than
# an empty or single-colour page (a few kB).
size=$(stat -c %s "$out/webgl2.png")
if [ "$size" -lt 100000 ]; then
    echo "web/browser_test.sh: FAILED: webgl2: the screenshot is $size bytes: blank?" >&2
    exit 1
fi

open_page webgpu --enable-unsafe-webgpu --use-webgpu-adapter=swiftshader --enable-unsafe-swiftshader
check_console webgpu
if ! grep -q 'backend: BrowserWebGpu' "$out/webgpu.log"; then
    echo "web/browser_test.sh: FAILED: webgpu: eframe did not take WebGPU" >&2
    exit 1
fi

mkdir -p target/web-test
cp "$out/webgl2.png" target/web-test/webgl2.png
echo "web/browser_test.sh: ok: the lab opened on WebGL2 (screenshot $size bytes, target/web-test/webgl2.png) and on WebGPU, without console errors"
