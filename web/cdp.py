#!/usr/bin/env python3
"""Drives headless Chromium over the DevTools protocol for web/browser_test.sh (issue 21).

Chromium's --dump-dom with a virtual-time budget cannot wait for WebGPU work (the GPU
process's time is not the page's virtual time), so the test opens the page, then asks it in
real time. Standard library only: a minimal WebSocket client (RFC 6455, text frames) is below.

    cdp.py URL --wait JS [--print JS] [--screenshot PNG] [--console LOG] [--timeout S]
           [--size W,H] -- FLAGS

opens URL with Chromium's FLAGS, waits until the expression --wait is truthy, prints the
value of --print (a string), saves a screenshot, and writes the page's console messages and
uncaught exceptions to LOG, one per line. Exit 1 on a timeout (the page's state is printed).
"""

import argparse
import base64
import json
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request


class Socket:
    """A WebSocket client connection: text frames out (masked), frames in."""

    def __init__(self, url):
        rest = url.split("://", 1)[1]
        hostport, path = rest.split("/", 1)
        host, port = hostport.split(":")
        self.sock = socket.create_connection((host, int(port)))
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(
            (
                f"GET /{path} HTTP/1.1\r\nHost: {hostport}\r\nUpgrade: websocket\r\n"
                f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\n"
                "Sec-WebSocket-Version: 13\r\n\r\n"
            ).encode()
        )
        head = b""
        while b"\r\n\r\n" not in head:
            chunk = self.sock.recv(1)
            if not chunk:
                raise ConnectionError("the browser closed the DevTools connection")
            head += chunk
        if b" 101 " not in head.split(b"\r\n", 1)[0]:
            raise ConnectionError(f"no WebSocket upgrade: {head[:80]!r}")

    def send(self, text):
        payload = text.encode()
        n = len(payload)
        if n < 126:
            header = struct.pack("!BB", 0x81, 0x80 | n)
        elif n < 1 << 16:
            header = struct.pack("!BBH", 0x81, 0x80 | 126, n)
        else:
            header = struct.pack("!BBQ", 0x81, 0x80 | 127, n)
        mask = os.urandom(4)
        body = bytes(b ^ mask[k % 4] for k, b in enumerate(payload))
        self.sock.sendall(header + mask + body)

    def _exact(self, n):
        data = b""
        while len(data) < n:
            chunk = self.sock.recv(n - len(data))
            if not chunk:
                raise ConnectionError("the browser closed the DevTools connection")
            data += chunk
        return data

    def recv(self):
        message = b""
        while True:
            first, second = self._exact(2)
            n = second & 0x7F
            if n == 126:
                (n,) = struct.unpack("!H", self._exact(2))
            elif n == 127:
                (n,) = struct.unpack("!Q", self._exact(8))
            payload = self._exact(n)
            opcode = first & 0x0F
            if opcode == 8:
                raise ConnectionError("the browser closed the DevTools connection")
            if opcode in (0, 1, 2):
                message += payload
                if first & 0x80:
                    return message.decode()


class Page:
    """One page's DevTools session: commands, and the console collected on the way."""

    def __init__(self, ws_url):
        self.ws = Socket(ws_url)
        self.next_id = 0
        self.console = []
        # Other events, oldest first, for wait_event.
        self.events = []

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    raise RuntimeError(f"{method}: {msg['error']}")
                return msg.get("result", {})
            self._event(msg)

    def _event(self, msg):
        method, params = msg.get("method"), msg.get("params", {})
        if method == "Runtime.consoleAPICalled":
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", []))
            self.console.append(f"{params.get('type')}: {text}")
        elif method == "Runtime.exceptionThrown":
            d = params.get("exceptionDetails", {})
            text = d.get("exception", {}).get("description") or d.get("text")
            self.console.append(f"uncaught: {text}")
        elif method == "Log.entryAdded":
            e = params.get("entry", {})
            self.console.append(f"{e.get('level')}: {e.get('text')}")
        elif method:
            self.events.append((method, params))

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True)
        return r.get("result", {}).get("value")


    def wait_event(self, method, timeout, where=lambda params: True):
        """The parameters of the first event `method` (matching `where`) not yet taken; None
        if none came within `timeout` s."""
        deadline = time.time() + timeout
        while True:
            for k, (m, params) in enumerate(self.events):
                if m == method and where(params):
                    del self.events[k]
                    return params
            if time.time() > deadline:
                return None
            time.sleep(0.1)
            # A command's round trip reads the events that came meanwhile.
            self.evaluate("0")


def texts(page, text):
    """Where the lab drew `text` (index.html?texts: the page's #lab-texts map), as rectangles
    in the page's CSS pixels."""
    found = page.evaluate(
        "(() => { const m = document.getElementById('lab-texts'); "
        "const c = document.getElementById('lab').getBoundingClientRect(); "
        "return JSON.stringify({texts: JSON.parse(m.textContent || '[]'), x: c.x, y: c.y}); })()")
    found = json.loads(found)
    return [[r[0] + found["x"], r[1] + found["y"], r[2] + found["x"], r[3] + found["y"]]
            for r in (t["rect"] for t in found["texts"] if t["text"] == text)]


def click(page, x, y):
    """A left click at (x, y): the pointer moves there, presses and releases, as a user's."""
    for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
        page.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left",
                  buttons=1 if kind == "mousePressed" else 0,
                  clickCount=0 if kind == "mouseMoved" else 1)
        time.sleep(0.05)


def move(page, x, y):
    """The pointer moved to (x, y), nothing pressed."""
    page.call("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y, button="none",
              buttons=0)
    time.sleep(0.05)


def press_key(page, key, code, key_code):
    """A key pressed and released, as a keyboard's (`key` as the DOM names it)."""
    for kind in ("keyDown", "keyUp"):
        page.call("Input.dispatchKeyEvent", type=kind, key=key, code=code,
                  windowsVirtualKeyCode=key_code, nativeVirtualKeyCode=key_code)
        time.sleep(0.05)


def click_text(page, text):
    """Clicks the one place the lab drew `text` (a button's label); an error if it is not
    there, or there more than once."""
    rects = texts(page, text)
    if len(rects) != 1:
        raise RuntimeError(f"the lab shows {text!r} {len(rects)} times, not once")
    x0, y0, x1, y1 = rects[0]
    click(page, (x0 + x1) / 2, (y0 + y1) / 2)


def rest_and_click(page, text):
    """Clicks the one place the lab drew `text`, the pointer resting on it for half a second
    first, as a user's does."""
    rects = texts(page, text)
    if len(rects) != 1:
        raise RuntimeError(f"the lab shows {text!r} {len(rects)} times, not once")
    x0, y0, x1, y1 = rects[0]
    move(page, (x0 + x1) / 2, (y0 + y1) / 2)
    time.sleep(0.5)
    click(page, (x0 + x1) / 2, (y0 + y1) / 2)


def click_for_event(page, text, method, tries=3, wait=20):
    """Clicks where the lab drew `text` until the page sends the event `method`, the pointer
    resting on the button for half a second first, as a user's does (a press that arrives with
    the pointer's first move over it can be lost to the frame that sees the move: seen in CI
    with Chromium 156.0.8078.108, and here on the page's first click); a lost click is clicked
    again once the pointer has left the button. The event's parameters, or None after `tries`
    clicks."""
    for _ in range(tries):
        rest_and_click(page, text)
        got = page.wait_event(method, wait)
        if got:
            return got
        move(page, 2, 400)
    return None


def wait_for(page, expression, timeout):
    """Whether the page's `expression` became truthy within `timeout` s (real time)."""
    deadline = time.time() + timeout
    while time.time() < deadline:
        if page.evaluate(f"!!({expression})"):
            return True
        time.sleep(0.25)
    return False


def drop_files(page, paths, x, y):
    """Drags files from the disk onto the page at (x, y) and drops them there."""
    data = {"items": [], "files": [os.path.abspath(p) for p in paths], "dragOperationsMask": 1}
    for kind in ("dragEnter", "dragOver", "drop"):
        page.call("Input.dispatchDragEvent", type=kind, x=x, y=y, data=data)


def open_page(url, wait, show="''", size="1280,800", flags=(), timeout=120, screenshot=None,
              browser=None, act=None):
    """Opens `url` in a fresh headless Chromium with `flags`, waits (in real time, up to
    `timeout` s) until the expression `wait` is truthy, then runs `act(page)` (if given and
    the wait ended in time; it says whether it succeeded), saves a screenshot; the value of
    `show`, the console's lines, and whether the wait (and `act`) ended well."""
    browser = browser or shutil.which("chromium") or "chromium"
    profile = tempfile.mkdtemp(prefix="ltc-lab-chromium-")
    process = subprocess.Popen(
        [browser, "--headless=new", "--no-sandbox", "--disable-gpu-sandbox",
         "--remote-debugging-port=0", f"--user-data-dir={profile}", f"--window-size={size}",
         *flags, "about:blank"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )
    try:
        port_file = os.path.join(profile, "DevToolsActivePort")
        deadline = time.time() + 30
        while not os.path.exists(port_file) or not open(port_file).read().strip():
            if time.time() > deadline or process.poll() is not None:
                raise RuntimeError("Chromium did not open its DevTools port")
            time.sleep(0.1)
        port = open(port_file).read().split()[0]
        targets = json.load(urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list"))
        page = Page(next(t for t in targets if t["type"] == "page")["webSocketDebuggerUrl"])
        page.call("Runtime.enable")
        page.call("Log.enable")
        page.call("Page.enable")
        page.call("Page.navigate", url=url)
        done = wait_for(page, wait, timeout)
        if done and act:
            done = act(page)
        if screenshot:
            shot = page.call("Page.captureScreenshot", format="png")
            with open(screenshot, "wb") as f:
                f.write(base64.b64decode(shot["data"]))
        shown = page.evaluate(show)
        # Messages that arrived after the last command.
        page.ws.sock.settimeout(0.5)
        try:
            while True:
                page._event(json.loads(page.ws.recv()))
        except (socket.timeout, ConnectionError):
            pass
        return shown, page.console, done
    finally:
        process.terminate()
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
        shutil.rmtree(profile, ignore_errors=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("url")
    ap.add_argument("--wait", required=True)
    ap.add_argument("--print", dest="show", default="''")
    ap.add_argument("--screenshot")
    ap.add_argument("--console")
    ap.add_argument("--timeout", type=float, default=120)
    ap.add_argument("--size", default="1280,800", help="the window's size, W,H")
    ap.add_argument("--browser")
    a, flags = ap.parse_known_args()
    flags = [f for f in flags if f != "--"]
    shown, console, done = open_page(a.url, a.wait, a.show, a.size, flags, a.timeout,
                                     a.screenshot, a.browser)
    if a.console:
        with open(a.console, "w") as f:
            f.write("\n".join(console) + "\n")
    print(shown if shown is not None else "")
    if not done:
        sys.exit(f"cdp.py: waited {a.timeout:.0f} s for {a.wait}")


if __name__ == "__main__":
    main()
