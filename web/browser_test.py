#!/usr/bin/env python3
"""The lab in a real browser (issue 21), run by web/browser_test.sh on dist/ served at URL:

1. index.html#selfcheck on WebGPU (SwiftShader): paper-100 at 160x120 by ltc-fast and brdf
   on the browser's GPU agrees with the CPU reference at the parity tolerance.
2. The lab on WebGL2 (WebGPU off): its CPU path draws the plane; all five panels are shown at
   1920x1080; the screenshot is not blank.
3. The lab on WebGPU: it shades on the GPU and finishes the plane.
4. A shared link round-trips: a hand-made #view=… opens, and the page reports the view it
   restored; a broken one opens the defaults.
5. Files dropped on the window are taken: a scene, a table, a study.
6. Files by the picker and downloads, with the buttons found by their labels on the page's
   map of the lab's texts (index.html?texts): a picked scene is taken; *save* downloads it,
   *screenshot* downloads the window as a PNG.
7. A refit runs in steps over the frames and ends with its result shown (its frames' gaps
   are printed, not asserted: speed is for benchmarks).
8. The lesson: #lesson=paper&step=7 opens that step (its title, its panel) on WebGL2 and on
   WebGPU, and *next*, clicked by its label, walks on to the last step.
9. No console errors in any run.

    browser_test.py URL OUTDIR     prints one line per check; exit 1 on the first failure
"""

import base64
import json
import os
import re
import sys
import time
import zlib

sys.path.insert(0, os.path.dirname(__file__))
from cdp import (  # noqa: E402
    click_for_event, click_text, drop_files, move, open_page, press_key, rest_and_click,
    wait_for,
)

WEBGPU = ["--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader",
          "--enable-unsafe-swiftshader"]
# WebGL2 on SwiftShader without the deprecation warning; and no WebGPU.
WEBGL2 = ["--enable-unsafe-swiftshader", "--disable-features=WebGPU"]
STATE = "document.getElementById('lab-state').textContent"
SETTLED = f"(s => s && JSON.parse(s).settled_ms !== null)({STATE})"

# Console lines that are failures: a panic, an uncaught exception, a WGSL or wgpu error, the
# page's own messages, a resource that failed to load.
FAILURE = re.compile(
    r"panicked|uncaught|error while|could not load|could not start|stopped:|wgpu error|"
    r"validation error|failed to load resource|^error:|error: \[wgpu", re.I)


def fail(what):
    print(f"web/browser_test.py: FAILED: {what}", file=sys.stderr)
    sys.exit(1)


def check_console(name, console, out):
    with open(os.path.join(out, f"{name}.console.log"), "w") as f:
        f.write("\n".join(console) + "\n")
    bad = [line for line in console if FAILURE.search(line)]
    if bad:
        fail(f"{name}: console errors:\n  " + "\n  ".join(l[:400] for l in bad))


def grid(state):
    """The grid's panels the lab's last frame drew (the side panel aside)."""
    return [p for p in state["panels"] if p != "controls"]


def lab(url, name, out, flags, fragment="", size="1920,1080", timeout=240, wait=SETTLED,
        act=None):
    """Opens the lab, waits until it has drawn everything (or `wait`), runs `act`, and gives
    its report."""
    shot = os.path.join(out, f"{name}.png")
    shown, console, done = open_page(url + fragment, wait, STATE, size, flags, timeout, shot,
                                     act=act)
    check_console(name, console, out)
    if not done:
        fail(f"{name}: the lab did not finish drawing in {timeout} s; it reports {shown!r}")
    return json.loads(shown), shot


def view_text(view):
    """The RON text of a view string (app/link.rs: v1. + URL-safe base64 of raw deflate)."""
    body = view.removeprefix("v1.")
    packed = base64.urlsafe_b64decode(body + "=" * (-len(body) % 4))
    return zlib.decompress(packed, -15).decode()


def view_string(ron_text):
    c = zlib.compressobj(9, zlib.DEFLATED, -15)
    packed = c.compress(ron_text.encode()) + c.flush()
    return "v1." + base64.urlsafe_b64encode(packed).decode().rstrip("=")


def main():
    url, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)

    # 1. The self-check on WebGPU.
    shown, console, done = open_page(
        url + "#selfcheck", "document.getElementById('selfcheck').textContent",
        "document.getElementById('selfcheck').textContent", flags=WEBGPU, timeout=180)
    check_console("selfcheck", console, out)
    if not done:
        fail("selfcheck: no result in 180 s")
    check = json.loads(shown)
    with open(os.path.join(out, "selfcheck.json"), "w") as f:
        json.dump(check, f, indent=1)
    if check.get("backend") != "webgpu" or not check.get("passed"):
        fail(f"selfcheck: {shown}")
    if not check["max_rel_diff"] <= check["tolerance"]:
        fail(f"selfcheck: max_rel_diff {check['max_rel_diff']} over {check['tolerance']}")
    print(f"web/browser_test.py: ok: selfcheck on WebGPU ({check['adapter']}): max_rel_diff "
          f"{check['max_rel_diff']:.2e} <= {check['tolerance']:.0e}; first GPU frame read back "
          f"{check['first_frame_ms']} ms after navigation")

    # The self-check without WebGPU says so (and what the CPU takes).
    shown, console, done = open_page(
        url + "#selfcheck", "document.getElementById('selfcheck').textContent",
        "document.getElementById('selfcheck').textContent", flags=WEBGL2, timeout=120)
    check_console("selfcheck-webgl2", console, out)
    cpu_check = json.loads(shown) if done else {}
    if cpu_check.get("backend") != "webgl2" or cpu_check.get("max_rel_diff") is not None:
        fail(f"selfcheck without WebGPU: {shown!r}")
    print(f"web/browser_test.py: ok: selfcheck without WebGPU reports webgl2 "
          f"(CPU image at {cpu_check['first_frame_ms']} ms)")

    # 2. The lab on WebGL2: all panels, drawn by the CPU.
    state, shot = lab(url, "webgl2", out, WEBGL2)
    if state["shading"] != "cpu":
        fail(f"webgl2: the plane is not on the CPU path: {state}")
    panels = ["lobe", "matrix", "plane", "clipping", "chart"]
    if grid(state) != panels:
        fail(f"webgl2: the panels shown are {grid(state)}, not all five")
    # The panels' text, plots and the shaded plane compress to far more than an empty or
    # single-colour page (a few kB).
    size = os.path.getsize(shot)
    if size < 200_000:
        fail(f"webgl2: the screenshot is {size} bytes: blank?")
    print(f"web/browser_test.py: ok: the lab on WebGL2 (CPU plane): five panels, first frame "
          f"{state['first_frame_ms']} ms, everything drawn {state['settled_ms']} ms after "
          f"navigation; screenshot {size} bytes")

    # 3. The lab on WebGPU: the plane shaded on the browser's GPU, to the last light.
    state, _ = lab(url, "webgpu", out, WEBGPU)
    if state["shading"] != "gpu" or grid(state) != panels:
        fail(f"webgpu: {state}")
    if state["plane"][0] != state["plane"][1]:
        fail(f"webgpu: the plane stopped at {state['plane']}")
    print(f"web/browser_test.py: ok: the lab on WebGPU ({state['device']}): first frame "
          f"{state['first_frame_ms']} ms, plane ({state['plane'][1]} lights) and everything "
          f"drawn {state['settled_ms']} ms after navigation")

    # 4. A link round-trips: a view made here opens, and the page reports it back.
    sent = view_string("(lab:(lobe_view:(theta_o_deg:30.0),stage:(plane:(half_size:2.0),"
                       "camera:(position:[0.0,-3.4,2.8],target:[0.0,-0.1,0.0],"
                       "fov_y_degrees:40.0)),"
                       "material:(base_color:[0.5,0.5,0.5],f0:0.04,alpha:0.61)),"
                       "generated:Some(40),window:(maximised:Some(Matrix)))")
    state, _ = lab(url, "link", out, WEBGL2, fragment="#view=" + sent)
    restored = view_text(state["view"])
    for part in ["theta_o_deg:30.0", "alpha:0.61", "maximised:Some(Matrix)",
                 "generated:Some(40)"]:
        if part not in restored:
            fail(f"link: the view opened from the link lacks {part}: {restored[:600]}")
    if grid(state) != ["matrix"]:
        fail(f"link: the link's panel is not the one shown: {grid(state)}")
    print("web/browser_test.py: ok: a #view= link opened its view (θo 30°, α 0.61, 40 lights, "
          "the matrix panel maximised) and the page reported it back")

    # A broken link: the defaults, and no crash.
    state, _ = lab(url, "broken-link", out, WEBGL2, fragment="#view=v1.broken!")
    if grid(state) != panels or "theta_o_deg:45.0" not in view_text(state["view"]):
        fail(f"broken link: not the defaults: {grid(state)}")
    print("web/browser_test.py: ok: a broken #view= link opened the defaults")

    # A hostile link: a view that decodes, with values no widget would write. It opens drawn
    # (the plane finished), each value refused or clamped by name in the notices bar.
    for hostile, field in [("(plane:(divider:NaN))", "divider"),
                           ("(lab:(overrides:(intensity_scale:NaN)))", "intensity"),
                           ("(lab:(overrides:(range:1e-300)))", "range")]:
        state, _ = lab(url, "hostile-link", out, WEBGL2, fragment="#view=" + view_string(hostile),
                       timeout=120)
        if state["plane"][0] != state["plane"][1] or field not in (state["message"] or ""):
            fail(f"hostile link {hostile}: plane {state['plane']}, message {state['message']!r}")
    print("web/browser_test.py: ok: hostile #view= links (NaN divider, NaN intensity, range "
          "1e-300) opened drawn, each field named")

    # 8. The lesson, from a link.
    lessons(url, out)

    # 9. Rect and disk lights, from the polygon lesson's steps.
    shaped_lights(url, out)

    # 5. Files dropped on the window.
    drops(url, out)

    # 6. and 7. Files by the picker, downloads, and a refit, by the buttons' labels.
    picks_downloads_and_refit(url, out)


def drops(url, out):
    """Drops a scene, then a table, then a study on the lab, reading its report after each."""
    root = os.path.join(os.path.dirname(__file__), "..")
    scene = os.path.join(out, "dropped-scene.toml")
    with open(scene, "w") as f:
        f.write("[plane]\nhalf_size = 2.0\n[material]\nbase_color = [0.5, 0.5, 0.5]\n"
                "f0 = 0.04\nalpha = 0.77\n[camera]\nposition = [0.0, -3.4, 2.8]\n"
                "target = [0.0, 0.0, 0.0]\nfov_y_degrees = 40.0\n"
                "[[lights]]\nposition = [0.1, 0.2, 0.3]\nintensity = 0.5\n")
    message = f"(s => s && JSON.parse(s).message)({STATE})"
    steps = [
        (scene, "loaded dropped-scene.toml"),
        (os.path.join(root, "luts", "ltc_point.exr"), "shading with ltc_point.exr"),
        (os.path.join(root, "assets", "study", "reference.csv"), "plotting reference.csv"),
    ]
    seen = []

    def act(page):
        for path, said in steps:
            # Onto the plane panel, in the middle of the window.
            drop_files(page, [path], 1000, 300)
            if not wait_for(page, f"({message} || '').includes({json.dumps(said)})", 60):
                seen.append(f"after dropping {os.path.basename(path)}: {page.evaluate(message)!r}")
                return False
            seen.append(page.evaluate(STATE))
        return True

    shown, console, done = open_page(url, SETTLED, STATE, "1920,1080", WEBGL2, 240, act=act)
    check_console("drops", console, out)
    if not done:
        fail(f"drops: {seen[-1] if seen else shown}")
    after_scene = view_text(json.loads(seen[0])["view"])
    if "alpha:0.77" not in after_scene:
        fail(f"drops: the dropped scene is not the lab's: {after_scene[:300]}")
    print("web/browser_test.py: ok: a scene, a table (.exr) and a study (.csv) dropped on the "
          "window were taken")


TEXTS = "document.getElementById('lab-texts').textContent"


def lessons(url, out):
    """Opens #lesson=paper&step=7 on WebGL2 and WebGPU: the page reports that step, its title
    and its panel; then *next*, clicked where the lab drew it, walks to the last step."""
    lesson = f"JSON.parse({STATE}).lesson"
    for name, flags in [("lesson-webgl2", WEBGL2), ("lesson-webgpu", WEBGPU)]:
        walked = {}

        def act(page):
            first = json.loads(page.evaluate(f"JSON.stringify({lesson})"))
            walked["first"] = first
            for step in range(first["step"] + 1, first["steps"] + 1):
                # A click a slow software-GL frame loses (seen with Chromium 156.0.8078.108 on
                # the commit that passed CI before it) is clicked again after the pointer leaves
                # the button, then the bar's key (→, as its hover text says) is pressed, as a
                # user would; the step must then be the next one exactly.
                for attempt in range(4):
                    try:
                        if attempt < 2:
                            click_text(page, "next")
                        else:
                            press_key(page, "ArrowRight", "ArrowRight", 39)
                    except RuntimeError as e:
                        walked["why"] = f"step {step - 1}: {e}"
                        return False
                    if wait_for(page, f"{lesson}.step >= {step}", 20):
                        break
                    move(page, 2, 400)
                if not wait_for(page, f"{lesson}.step === {step}", 1):
                    walked["why"] = f"next did not reach step {step}: {page.evaluate(STATE)}"
                    return False
            walked["last"] = json.loads(page.evaluate(f"JSON.stringify({lesson})"))
            return True

        shown, console, done = open_page(url + "?texts#lesson=paper&step=7", SETTLED, STATE,
                                         "1920,1080", flags, 240,
                                         os.path.join(out, f"{name}.png"), act=act)
        check_console(name, console, out)
        if not done:
            fail(f"{name}: {walked.get('why', shown)}")
        state = json.loads(shown)
        first = walked.get("first") or {}
        if first.get("step") != 7 or not first.get("title", "").startswith("Case 1"):
            fail(f"{name}: #lesson=paper&step=7 opened {first!r}")
        if "why" in walked or walked["last"]["step"] != first["steps"]:
            fail(f"{name}: {walked.get('why', walked)}")
        if grid(state) != ["chart"]:
            fail(f"{name}: the last step's panel is not the one shown: {grid(state)}")
        print(f"web/browser_test.py: ok: #lesson=paper&step=7 opened step 7 ({first['title']}) "
              f"on {state['shading'].upper()} shading, and next walked to step "
              f"{walked['last']['step']} of {first['steps']}")


def shaped_lights(url, out):
    """Opens the polygon lesson's clipping step (three rects across and below the horizon) and
    its disk step, on WebGPU (shaded on the GPU, every light to the last) and on WebGL2 (the CPU
    plane): each plane finishes, the view holds the lights' shapes, and the page is not blank."""
    for step, shape, title in [(4, "half_u", "Clipping a polygon"), (6, "normal", "A disk")]:
        for name, flags, shading in [("webgpu", WEBGPU, "gpu"), ("webgl2", WEBGL2, "cpu")]:
            tag = f"lesson-polygon-{step}-{name}"
            state, shot = lab(url + "?texts", tag, out, flags,
                              fragment=f"#lesson=polygon&step={step}")
            lesson = state.get("lesson") or {}
            if state["shading"] != shading or state["plane"][0] != state["plane"][1]:
                fail(f"{tag}: {state['shading']} plane {state['plane']}")
            if not lesson.get("title", "").startswith(title):
                fail(f"{tag}: opened {lesson!r}")
            if shape not in view_text(state["view"]):
                fail(f"{tag}: the view lacks the lights' {shape}")
            if name == "webgl2" and os.path.getsize(shot) < 100_000:
                fail(f"{tag}: the screenshot is {os.path.getsize(shot)} bytes: blank?")
        print(f"web/browser_test.py: ok: #lesson=polygon&step={step} ({title}…) shaded its "
              f"lights ({shape}) to the last on WebGPU and on the CPU under WebGL2")


def watch_frames(page):
    """Starts timing the page's animation frames afresh (see `frames`)."""
    page.evaluate("""(() => { if (window.gaps) window.gaps.stop = true;
        const g = window.gaps = {longest: 0, frames: 0, last: performance.now()};
        (function frame(t) { if (g.stop) return;
          g.longest = Math.max(g.longest, t - g.last); g.last = t; g.frames++;
          requestAnimationFrame(frame); })(performance.now()); })(); 0""")


def frames(page):
    """The page's animation frames since `watch_frames`: how many, and the longest gap (ms)."""
    return json.loads(page.evaluate("JSON.stringify(window.gaps)"))


def picks_downloads_and_refit(url, out):
    """Picks a scene with the browser's file picker (answered over DevTools), downloads it
    and a screenshot, then refits a cell: each by clicking the button the lab labelled so."""
    downloads = os.path.abspath(os.path.join(out, "downloads"))
    os.makedirs(downloads, exist_ok=True)
    scene = os.path.abspath(os.path.join(out, "picked-scene.toml"))
    with open(scene, "w") as f:
        f.write("[plane]\nhalf_size = 2.0\n[material]\nbase_color = [0.5, 0.5, 0.5]\n"
                "f0 = 0.04\nalpha = 0.66\n[camera]\nposition = [0.0, -3.4, 2.8]\n"
                "target = [0.0, 0.0, 0.0]\nfov_y_degrees = 40.0\n"
                "[[lights]]\nposition = [0.1, 0.2, 0.3]\nintensity = 0.5\n")
    message = f"(JSON.parse({STATE}).message || '')"
    found = {}

    def downloaded(page, button, name):
        if not click_for_event(page, button, "Browser.downloadWillBegin"):
            found["why"] = f"{button}: three clicks began no download; the lab says " \
                           f"{page.evaluate(message)!r} (frames: {frames(page)})"
            return None
        done = page.wait_event("Browser.downloadProgress", 30,
                               lambda p: p.get("state") in ("completed", "canceled"))
        path = os.path.join(downloads, name)
        if not done or done["state"] != "completed" or not os.path.exists(path):
            found["why"] = f"{button}: no download of {name} ({done}); the lab says " \
                           f"{page.evaluate(message)!r}"
            return None
        return path

    def act(page):
        page.call("Page.setInterceptFileChooserDialog", enabled=True)
        page.call("Browser.setDownloadBehavior", behavior="allow", downloadPath=downloads,
                  eventsEnabled=True)
        watch_frames(page)
        # The page's first click focuses the canvas and was seen to open nothing: a click on
        # the side panel's heading (a label, which does nothing) takes it first.
        rest_and_click(page, "LTC Lab")
        time.sleep(1)
        # The scene's "load" opens the picker; DevTools answers it with the file.
        chooser = click_for_event(page, "load", "Page.fileChooserOpened")
        if not chooser:
            found["why"] = f"load: three clicks opened no file picker (frames: {frames(page)})"
            return False
        page.call("DOM.setFileInputFiles", files=[scene], backendNodeId=chooser["backendNodeId"])
        if not wait_for(page, f"{message}.includes('loaded picked-scene.toml')", 60):
            found["why"] = f"the picked scene was not taken: {page.evaluate(message)!r}"
            return False
        found["view"] = json.loads(page.evaluate(STATE))["view"]
        found["scene"] = downloaded(page, "save", "scene.toml")
        found["png"] = downloaded(page, "screenshot", "ltc-lab.png")
        found["canvas"] = page.evaluate(
            "(c => [c.width, c.height])(document.getElementById('lab'))")
        if not (found["scene"] and found["png"]):
            return False
        # A refit by ltc_code's fitter, its frames timed by the page's own animation frames.
        watch_frames(page)
        # The refit's start is seen (the matrix panel busy, or the refit's result) before its
        # end is awaited: a click a slow software-GL frame loses (CI, Chromium 156.0.8078.108)
        # is clicked again once the pointer has left. The result is read where it always
        # shows, the lobe panel's "table A: classic (refitted)": the matrix panel's own line
        # may lie below its scrolled fold.
        refitting = f"JSON.parse({STATE}).working.some(w => /matrix/i.test(w))"
        refitted = f"{TEXTS}.includes('(refitted)')"
        for attempt in range(3):
            try:
                rest_and_click(page, "ltc_code")
            except RuntimeError as e:
                found["why"] = f"refit: {e}"
                return False
            if wait_for(page, f"{refitting} || {refitted}", 20):
                break
            move(page, 2, 400)
        else:
            found["why"] = "three clicks on ltc_code did not start a refit"
            return False
        if not wait_for(page, f"!({refitting}) && {refitted}", 240):
            found["why"] = f"the refit did not end with its result shown within 240 s: " \
                           f"{page.evaluate(STATE)[:300]}"
            return False
        found["gaps"] = frames(page)
        return True

    # Clicks were lost here and in CI (the picker or a download not opened) until the lab kept
    # clicks over slow frames (docs/design.md §5.15: a press and its release 1-2 s apart on
    # SwiftShader). A fresh browser again where a click is still lost three times over; every
    # step must pass within one page, and each failed page is printed with its frame times.
    for attempt in range(3):
        for name in os.listdir(downloads):
            os.remove(os.path.join(downloads, name))
        found.clear()
        shown, console, done = open_page(url + "?texts", SETTLED, STATE, "1920,1080", WEBGL2,
                                         240, os.path.join(out, "picks.png"), act=act)
        if done:
            break
        print(f"web/browser_test.py: picks, page {attempt + 1} of 3: "
              f"{found.get('why', shown)}; again in a fresh browser", file=sys.stderr)
    check_console("picks", console, out)
    if not done:
        fail(f"picks: {found.get('why', shown)}")
    if "alpha:0.66" not in view_text(found["view"]):
        fail(f"picks: the picked scene is not the lab's: {view_text(found['view'])[:300]}")
    with open(found["scene"]) as f:
        saved = f.read()
    if not re.search(r"alpha = 0\.66\b", saved):
        fail(f"picks: the downloaded scene is not the lab's: {saved[:300]!r}")
    with open(found["png"], "rb") as f:
        head = f.read(24)
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    if head[:8] != b"\x89PNG\r\n\x1a\n" or [width, height] != found["canvas"]:
        fail(f"picks: the screenshot is not a PNG of the canvas {found['canvas']}: {head!r}")
    print("web/browser_test.py: ok: a scene picked with the file picker was taken; save "
          f"downloaded it, screenshot a {width}x{height} PNG of the window")
    gaps = found["gaps"]
    print(f"web/browser_test.py: ok: a refit (ltc_code) ran over {gaps['frames']} animation "
          f"frames and showed its result; longest frame {gaps['longest']:.0f} ms (WebGL2 on "
          "SwiftShader)")


if __name__ == "__main__":
    main()
