#!/usr/bin/python3
"""Opens report.html in headless Chromium, driven through the DevTools protocol, and checks it
as a user would see it:

- no console error and no uncaught exception while it loads and while it is used;
- the 3D view is drawn: a screenshot of the scene area with a non-trivial number of distinct
  colours and little empty background;
- hovering the SOC chart marks the place on the route; the mode buttons switch plans; dragging
  orbits the camera and the wheel zooms it.

Usage: report_browser_test.py REPORT.html [--plans ceiling,free] [--min-photos N]
                              [--screenshot PNG] [--show PLAN] [--view PRESET]
Exit 0: passed; 1: failed (the reasons printed); 77: skipped, no browser can run here (ctest's
SKIP_RETURN_CODE, with the reason printed).
"""
import argparse
import base64
import io
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SKIP = 77
WIDTH, HEIGHT = 1400, 900


def skip(reason):
    print(f"SKIPPED: {reason}")
    sys.stderr.write(f"report_browser_test: skipped: {reason}\n")
    sys.exit(SKIP)


def fail(reasons):
    for reason in reasons:
        print(f"FAILED: {reason}")
    sys.exit(1)


try:
    import websocket  # python3-websocket
except ImportError:
    skip("python3-websocket is not installed (scripts/setup installs it)")
try:
    from PIL import Image  # python3-pil, with matplotlib
except ImportError:
    skip("python3-pil is not installed (scripts/setup installs it)")


def find_browser():
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        path = shutil.which(name)
        if path:
            return path
    return None


class DevTools:
    """One page of a headless browser, over the DevTools protocol's websocket."""

    def __init__(self, browser, profile):
        flags = [browser, "--headless=new", "--remote-debugging-port=0", f"--user-data-dir={profile}",
                 f"--window-size={WIDTH},{HEIGHT}", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                 "--use-gl=angle", "--no-first-run", "--no-default-browser-check", "--hide-scrollbars",
                 "--mute-audio", "about:blank"]
        if os.geteuid() == 0:
            flags.insert(1, "--no-sandbox")  # Chromium refuses to run its sandbox as root
        # Its own process group: closing ends the renderers and helpers too, which otherwise may
        # still write into the profile while the temporary directory is removed.
        self.process = subprocess.Popen(flags, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                        start_new_session=True)
        endpoint, log = None, []
        deadline = time.time() + 60
        while time.time() < deadline and endpoint is None:
            line = self.process.stderr.readline()
            if not line:
                if self.process.poll() is not None:
                    break
                continue
            log.append(line.strip())
            match = re.search(r"DevTools listening on (ws://\S+)", line)
            if match:
                endpoint = match.group(1)
        if endpoint is None:
            self.close()
            skip("headless Chromium did not start: " + " | ".join(log[-3:]))
        self.socket = websocket.create_connection(endpoint, timeout=60, suppress_origin=True)
        self.next_id = 0
        self.events = []
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]

    def call(self, method, params=None, session=True):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session and getattr(self, "session", None):
            message["sessionId"] = self.session
        self.socket.send(json.dumps(message))
        while True:
            reply = json.loads(self.socket.recv())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            self.events.append(reply)

    def evaluate(self, expression):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails'].get('text')} "
                               f"{result['exceptionDetails'].get('exception', {}).get('description', '')}")
        return result["result"].get("value")

    def errors(self):
        """Console errors, uncaught exceptions and error log entries seen so far."""
        found = []
        for event in self.events:
            method, params = event.get("method"), event.get("params", {})
            if method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
                found.append("console." + params["type"] + ": " +
                             " ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
            elif method == "Runtime.exceptionThrown":
                details = params.get("exceptionDetails", {})
                found.append("uncaught: " + details.get("exception", {}).get("description", details.get("text", "")))
            elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
                found.append("log: " + params["entry"].get("text", ""))
        return found

    def mouse(self, kind, x, y, **extra):
        self.call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, **extra})

    def screenshot(self):
        data = self.call("Page.captureScreenshot", {"format": "png"})["data"]
        return Image.open(io.BytesIO(base64.b64decode(data))).convert("RGB")

    def close(self):
        try:
            self.socket.close()
        except Exception:
            pass
        for sig in (signal.SIGTERM, signal.SIGKILL):
            try:
                os.killpg(self.process.pid, sig)
            except ProcessLookupError:
                break
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                pass
        # Whatever of the group outlived its leader goes before the profile does.
        for _ in range(100):
            try:
                os.killpg(self.process.pid, signal.SIGKILL)
            except ProcessLookupError:
                break
            time.sleep(0.05)


def scene_colours(image, rect):
    """Distinct colours in the scene area, and the share of pixels that are not background."""
    scene = image.crop((int(rect["x"]), int(rect["y"]), int(rect["x"] + rect["width"]), int(rect["y"] + rect["height"])))
    colours = scene.getcolors(maxcolors=1 << 24)
    background = max(colours)[1]
    drawn = sum(count for count, colour in colours if colour != background)
    return len(colours), drawn / (scene.width * scene.height)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("report")
    parser.add_argument("--plans", default="", help="the plan names expected, comma separated")
    parser.add_argument("--min-photos", type=int, default=0, help="photo frusta the first plan must show")
    parser.add_argument("--screenshot", help="save the page here (PNG) after the checks")
    parser.add_argument("--show", help="the plan on the saved screenshot")
    parser.add_argument("--view", help="the camera preset on the saved screenshot")
    parser.add_argument("--hover", type=float, default=0.4, help="on the saved screenshot, the chart hovered at this share of the time")
    args = parser.parse_args()
    report = os.path.abspath(args.report)
    if not os.path.exists(report):
        fail([f"{report} does not exist"])
    browser = find_browser()
    if browser is None:
        skip("no Chromium on PATH (scripts/setup installs Debian's chromium)")

    problems = []
    with tempfile.TemporaryDirectory(prefix="ceilplan-chromium-") as profile:
        page = DevTools(browser, profile)
        try:
            for domain in ("Runtime.enable", "Log.enable", "Page.enable"):
                page.call(domain)
            page.call("Emulation.setDeviceMetricsOverride",
                      {"width": WIDTH, "height": HEIGHT, "deviceScaleFactor": 1, "mobile": False})
            page.call("Page.navigate", {"url": "file://" + report})
            deadline = time.time() + 120
            ready = False
            while time.time() < deadline:
                ready = page.evaluate("!!(window.ceilplanReport && window.ceilplanReport.ready)")
                if ready or page.errors():
                    break
                time.sleep(0.25)
            if not ready:
                fail(page.errors() + ["the report did not signal ready within 120 s"])

            stats = page.evaluate("window.ceilplanReport.stats")
            names = page.evaluate("window.ceilplanReport.planNames")
            if args.plans and names != args.plans.split(","):
                problems.append(f"plans {names}, expected {args.plans}")
            if stats["voxels"] <= 0:
                problems.append("no structure voxels")
            if stats["photos"][0] < args.min_photos:
                problems.append(f"{stats['photos'][0]} photo frusta, expected at least {args.min_photos}")

            # The 3D view is drawn.
            rect = page.evaluate("(() => { const r = document.getElementById('view').getBoundingClientRect();"
                                 " return {x: r.x, y: r.y, width: r.width, height: r.height}; })()")
            distinct, drawn = scene_colours(page.screenshot(), rect)
            print(f"scene: {distinct} distinct colours, {100 * drawn:.1f} % of the pixels drawn, "
                  f"{stats['voxels']} voxels, samples {stats['samples']}, photos {stats['photos']}, patches {stats['patches']}")
            if distinct < 200:
                problems.append(f"the scene shows only {distinct} distinct colours: the canvas is not drawn")
            if drawn < 0.05:
                problems.append(f"only {100 * drawn:.1f} % of the scene differs from the background")

            # Hovering the chart marks the place on the route.
            chart = page.evaluate("(() => { const r = document.getElementById('chart').getBoundingClientRect();"
                                  " return {x: r.x, y: r.y, width: r.width, height: r.height}; })()")
            y = chart["y"] + chart["height"] / 2
            positions = []
            for share in (0.3, 0.6):
                x = chart["x"] + 48 + share * (chart["width"] - 48 - 70)
                page.mouse("mouseMoved", x, y)
                positions.append(page.evaluate("window.ceilplanReport.markerPosition()"))
            if None in positions or positions[0] == positions[1]:
                problems.append(f"hovering the chart did not move the marker along the route: {positions}")
            tip = page.evaluate("document.getElementById('tooltip').textContent")
            if "SOC" not in tip:
                problems.append(f"hovering the chart showed no tooltip: '{tip}'")
            hovered = page.evaluate("window.ceilplanReport.hoverTime(0)")
            first = page.evaluate("[window.ceilplanReport.markerPosition(), null]")[0]
            if hovered["index"] != 0 or first is None:
                problems.append("hoverTime(0) did not mark the first sample")

            # Orbit with a left drag, zoom with the wheel.
            before = page.evaluate("window.ceilplanReport.cameraPosition()")
            cx, cy = rect["x"] + rect["width"] / 2, rect["y"] + rect["height"] / 2
            page.mouse("mousePressed", cx, cy, button="left", clickCount=1)
            for step in range(1, 6):
                page.mouse("mouseMoved", cx + 30 * step, cy + 5 * step, button="left", buttons=1)
            page.mouse("mouseReleased", cx + 150, cy + 25, button="left", clickCount=1)
            orbited = page.evaluate("window.ceilplanReport.cameraPosition()")
            if orbited == before:
                problems.append("dragging did not orbit the camera")
            page.mouse("mouseWheel", cx, cy, deltaX=0, deltaY=-400)
            zoomed = page.evaluate("window.ceilplanReport.cameraPosition()")
            if zoomed == orbited:
                problems.append("the wheel did not zoom")

            # The mode buttons switch plans.
            if len(names) > 1:
                buttons = page.evaluate("Array.from(document.querySelectorAll('#modes button')).map(b => {"
                                        " const r = b.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2]; })")
                bx, by = buttons[1]
                page.mouse("mousePressed", bx, by, button="left", clickCount=1)
                page.mouse("mouseReleased", bx, by, button="left", clickCount=1)
                if page.evaluate("window.ceilplanReport.activePlan()") != names[1]:
                    problems.append(f"clicking '{names[1]} mode' did not switch the plan")

            if args.screenshot:
                page.evaluate(f"window.ceilplanReport.setPlan({json.dumps(args.show or names[0])})")
                page.evaluate(f"window.ceilplanReport.view({json.dumps(args.view or 'below-side')})")
                x = chart["x"] + 48 + args.hover * (chart["width"] - 48 - 70)
                page.mouse("mouseMoved", x, y)
                time.sleep(0.5)
                page.screenshot().save(args.screenshot)
                print(f"saved {args.screenshot}")
            time.sleep(0.5)
            page.evaluate("1")  # collect late events
            problems = page.errors() + problems
        finally:
            page.close()
    if problems:
        fail(problems)
    print("report_browser_test: passed")


if __name__ == "__main__":
    main()
