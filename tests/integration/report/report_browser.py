#!/usr/bin/env python3
"""Opens a report.html in headless Chromium and checks what a reader sees.

Drives Chromium over the DevTools protocol on --remote-debugging-pipe
(file descriptors 3 and 4, NUL-terminated JSON messages; standard library
only). Checks: the page finishes building (window.unimapReport.ready) with
no console error, no uncaught exception and no request to the network; the
WebGL view drew the map (pixels unlike the background in a screenshot of the
view with only the map layer shown); every plot and the map hold the
expected number of points. Prints what it measured; exits 1 with the reason
on the first failed check.

usage: report_browser.py CHROMIUM REPORT_HTML [--map-points N] [--plot ID=ROWS ...]
                         [--trajectory NAME=COUNT ...] [--loops N] [--screenshot OUT.png]
                         [--before-screenshot JS]
"""
import argparse
import base64
import fcntl
import json
import os
import select
import shutil
import subprocess
import sys
import tempfile
import time

BACKGROUND = (0x11, 0x15, 0x1C)  # the 3D view's clear colour (assets/viewer.js)
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--hide-scrollbars",
         "--remote-debugging-pipe"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


class Browser:
    """One Chromium process and one page session."""

    def __init__(self, chromium, profile):
        to_chrome = os.pipe()
        from_chrome = os.pipe()
        # Far from 3 and 4, so that dup2 onto them in the child always makes new, inheritable descriptors.
        self.chrome_in = fcntl.fcntl(to_chrome[0], fcntl.F_DUPFD_CLOEXEC, 100)
        self.chrome_out = fcntl.fcntl(from_chrome[1], fcntl.F_DUPFD_CLOEXEC, 100)
        for fd in (to_chrome[0], from_chrome[1]):
            os.close(fd)
        self.write_fd, self.read_fd = to_chrome[1], from_chrome[0]

        def child_fds():
            os.dup2(self.chrome_in, 3)
            os.dup2(self.chrome_out, 4)

        # Chromium's own log goes to a file (a pipe nobody reads could fill and stall it).
        self.log_file = os.path.join(profile, "chromium.log")
        with open(self.log_file, "wb") as log:
            self.process = subprocess.Popen([chromium] + FLAGS + ["--user-data-dir=" + profile, "about:blank"],
                                            preexec_fn=child_fds, close_fds=False, stdin=subprocess.DEVNULL,
                                            stdout=log, stderr=log)
        os.close(self.chrome_in)
        os.close(self.chrome_out)
        self.buffer = b""
        self.next_id = 0
        self.events = []
        self.session = None
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]

    def fail_with_log(self, what):
        with open(self.log_file, "rb") as log:
            fail(what + "; its log ends: " + log.read()[-2000:].decode(errors="replace"))

    def _read_message(self, deadline):
        while b"\0" not in self.buffer:
            left = deadline - time.time()
            if left <= 0 or not select.select([self.read_fd], [], [], left)[0]:
                fail("Chromium did not answer in time")
            chunk = os.read(self.read_fd, 1 << 20)
            if not chunk:
                self.fail_with_log("Chromium closed the DevTools pipe")
            self.buffer += chunk
        message, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(message)

    def call(self, method, params=None, timeout_s=60):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if self.session:
            message["sessionId"] = self.session
        try:
            os.write(self.write_fd, json.dumps(message).encode() + b"\0")
        except BrokenPipeError:
            self.fail_with_log("Chromium exited")
        deadline = time.time() + timeout_s
        while True:
            reply = self._read_message(deadline)
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    fail(method + ": " + json.dumps(reply["error"]))
                return reply.get("result", {})
            if "method" in reply:
                self.events.append(reply)

    def wait_event(self, method, timeout_s=60):
        deadline = time.time() + timeout_s
        while True:
            for event in self.events:
                if event["method"] == method:
                    return event
            self.events.append(self._read_message(deadline))

    def evaluate(self, expression, timeout_s=60):
        result = self.call("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                                "awaitPromise": True}, timeout_s)
        if "exceptionDetails" in result:
            fail("evaluating '" + expression[:80] + "...': " + json.dumps(result["exceptionDetails"])[:2000])
        return result["result"].get("value")

    def close(self):
        try:
            self.call("Browser.close", timeout_s=10)
        except SystemExit:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


def problems(events):
    """Console errors, uncaught exceptions and network requests among the events."""
    found = []
    for e in events:
        p = e.get("params", {})
        if e["method"] == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            found.append("console." + p["type"] + ": " + " ".join(str(a.get("value", a.get("description", "")))
                                                                 for a in p.get("args", [])))
        elif e["method"] == "Runtime.exceptionThrown":
            details = p.get("exceptionDetails", {})
            found.append("uncaught: " + details.get("exception", {}).get("description", details.get("text", "")))
        elif e["method"] == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            found.append("log error: " + p["entry"].get("text", "") + " " + p["entry"].get("url", ""))
        elif e["method"] == "Network.requestWillBeSent":
            url = p.get("request", {}).get("url", "")
            if not url.split(":", 1)[0] in ("file", "data", "about", "blob"):
                found.append("network request: " + url)
    return found


# Counts the screenshot's pixels inside the view's rectangle that differ from the background.
COUNT_PIXELS = """(async () => {
  const image = new Image();
  image.src = 'data:image/png;base64,%s';
  await image.decode();
  const r = %s;
  const canvas = document.createElement('canvas');
  canvas.width = r.width; canvas.height = r.height;
  const ctx = canvas.getContext('2d');
  ctx.drawImage(image, r.x, r.y, r.width, r.height, 0, 0, r.width, r.height);
  const px = ctx.getImageData(0, 0, r.width, r.height).data;
  let n = 0;
  for (let i = 0; i < px.length; i += 4) {
    if (Math.abs(px[i] - %d) + Math.abs(px[i + 1] - %d) + Math.abs(px[i + 2] - %d) > 40) ++n;
  }
  return {drawn: n, total: r.width * r.height};
})()"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("chromium")
    parser.add_argument("report")
    parser.add_argument("--map-points", type=int, help="points the map layer must hold")
    parser.add_argument("--plot", action="append", default=[], help="ID=ROWS: a plot and its rows")
    parser.add_argument("--trajectory", action="append", default=[], help="NAME=COUNT: a drawn trajectory")
    parser.add_argument("--loops", type=int, help="loop closures drawn")
    parser.add_argument("--screenshot", help="also save the page's first screen here (PNG)")
    parser.add_argument("--before-screenshot", default="true",
                        help="JavaScript run before the screenshot (e.g. unimapReport.setHeightCut(0.8))")
    args = parser.parse_args()

    profile = tempfile.mkdtemp(prefix="unimap-chromium-")
    browser = None
    try:
        browser = Browser(args.chromium, profile)
        for domain in ("Runtime", "Log", "Page", "Network"):
            browser.call(domain + ".enable")
        browser.call("Emulation.setDeviceMetricsOverride",
                     {"width": 1280, "height": 1000, "deviceScaleFactor": 1, "mobile": False})
        browser.call("Page.navigate", {"url": "file://" + os.path.abspath(args.report)})
        browser.wait_event("Page.loadEventFired", 120)
        state = browser.evaluate("window.unimapReport ? window.unimapReport.ready : 'no window.unimapReport'")
        if state is not True:
            fail("the page did not finish building: " + str(state) + "; " + "; ".join(problems(browser.events)))
        found = problems(browser.events)
        if found:
            fail("; ".join(found))

        counts = browser.evaluate("""(() => {
          const r = window.unimapReport, v = r.viewer, out = {plots: {}, trajectories: {}};
          for (const [id, g] of Object.entries(r.plots)) out.plots[id] = g.numRows();
          if (!v) return out;
          if (v.layers.map) out.map = v.layers.map.geometry.attributes.position.count;
          for (const t of r.data.trajectories) out.trajectories[t.name] = v.layers[t.name].geometry.attributes.position.count;
          if (v.layers.loops) out.loops = v.layers.loops.geometry.attributes.position.count / 2;
          return out; })()""")
        print("measured: " + json.dumps(counts, sort_keys=True))
        expected_plots = dict((k, int(v)) for k, v in (p.split("=") for p in args.plot))
        if counts["plots"] != expected_plots:
            fail("plots hold %s rows, expected %s" % (counts["plots"], expected_plots))
        for name, count in (t.split("=") for t in args.trajectory):
            if counts["trajectories"].get(name) != int(count):
                fail("trajectory %s holds %s points, expected %s" % (name, counts["trajectories"].get(name), count))
        if args.map_points is not None and counts.get("map") != args.map_points:
            fail("the map layer holds %s points, expected %d" % (counts.get("map"), args.map_points))
        if args.loops is not None and counts.get("loops", 0) != args.loops:
            fail("%s loop closures drawn, expected %d" % (counts.get("loops", 0), args.loops))

        # Every colouring the page offers (height, and intensity or map error when the map has them).
        modes = browser.evaluate("""(() => {
          const select = document.querySelector('select[aria-label="colour map by"]');
          if (!select) return [];
          const used = [];
          for (const option of select.options) {
            if (option.disabled) continue;
            select.value = option.value;
            select.dispatchEvent(new Event('change'));
            used.push(option.value);
          }
          select.value = 'height';
          select.dispatchEvent(new Event('change'));
          return used; })()""")
        print("colourings: " + ", ".join(modes))

        # The map alone, scrolled to the top of the view: its pixels in a real screenshot.
        rect = browser.evaluate("""(() => {
          const v = window.unimapReport.viewer;
          for (const name of Object.keys(v.layers)) v.setVisible(name, name === 'map');
          v.renderer.domElement.scrollIntoView();
          const r = v.renderer.domElement.getBoundingClientRect();
          return {x: Math.round(r.x), y: Math.round(r.y), width: Math.round(r.width), height: Math.round(r.height)};
        })()""")
        shot = browser.call("Page.captureScreenshot", {"format": "png"})["data"]
        pixels = browser.evaluate(COUNT_PIXELS % ((shot, json.dumps(rect)) + BACKGROUND))
        share = pixels["drawn"] / max(1, pixels["total"])
        print("map pixels: %d of %d in the 3D view (%.1f %%)" % (pixels["drawn"], pixels["total"], 100 * share))
        if args.map_points and share < 0.01:
            fail("the 3D view shows almost no map (%.2f %% of its pixels)" % (100 * share))
        found = problems(browser.events)
        if found:
            fail("; ".join(found))
        if args.screenshot:
            browser.evaluate("""(() => { const v = window.unimapReport.viewer;
              for (const name of Object.keys(v.layers)) v.setVisible(name, name !== 'odometry');
              window.scrollTo(0, 0); return true; })()""")
            browser.evaluate(args.before_screenshot)
            with open(args.screenshot, "wb") as out:
                out.write(base64.b64decode(browser.call("Page.captureScreenshot", {"format": "png"})["data"]))
            print("screenshot: " + args.screenshot)
    finally:
        if browser:
            browser.close()
        shutil.rmtree(profile, ignore_errors=True)
    print("PASS")


if __name__ == "__main__":
    main()
