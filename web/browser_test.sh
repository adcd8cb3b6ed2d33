#!/usr/bin/env bash
# The lab in a real browser: builds dist/ (web/build.sh --test), serves it on 127.0.0.1
# and runs web/browser_test.py, which opens it in headless Chromium: the self-check on
# WebGPU (SwiftShader), the lab on WebGL2 and on WebGPU, a shared link, dropped and picked
# files, downloads and a refit (the WebGPU canvas is not composited in headless Chromium
# here: its screenshots are black, so that path is read back, not seen).
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

# The test's build (`--test`: the `web-test` profile, the same code optimized less), which CI
# builds clean in minutes fewer than the shipped one.
bash web/build.sh --test
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

# The checks (web/browser_test.py) drive Chromium over the DevTools protocol (web/cdp.py):
# in real time, as WebGPU's work is not the page's virtual time.
start=$(date +%s)
python3 web/browser_test.py "$url" target/web-test
echo "web/browser_test.sh: ok in $(( $(date +%s) - start )) s: the self-check on WebGPU, the lab on WebGL2 and WebGPU, a shared link, files, downloads, a refit; pages and screenshots in target/web-test/"
