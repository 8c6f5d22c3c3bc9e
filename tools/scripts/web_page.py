#!/usr/bin/env python3
"""web_page.py - loads a page in headless Chromium, driven over the DevTools
protocol on a pipe (--remote-debugging-pipe: fd 3 in, fd 4 out, messages
ended by NUL; no port, no package), waits for its load, then evaluates an
expression, awaits it if it is a promise, and prints its value as JSON.
Every request the page makes is watched: one that is not file:, data: or
blob: (or under WEB_PAGE_ALLOW, a URL prefix: the server the page is loaded
from) fails the run. WEB_PAGE_LOG=FILE keeps Chromium's own log;
WEB_PAGE_SCREENSHOT=FILE.png saves the page (1000 x 620, or
WEB_PAGE_SIZE=WxH) once evaluated;
WEB_PAGE_FILE="SELECTOR=PATH" gives a file input that file (as a user
choosing it), before the expression runs; WEB_PAGE_MEMORY=FILE writes the
peak resident memory (VmHWM, kB) of the browser's renderer processes, the
page's tab among them, once evaluated; WEB_PAGE_PROFILE=FILE samples the
page's functions while the expression runs (the DevTools CPU profiler,
every 100 us) and writes each function's share of the samples, most first
(a module built with WEB_LDFLAGS_STRIP= keeps its functions' names).
tools/scripts/web-test.sh uses it.

  web_page.py CHROMIUM URL EXPRESSION [TIMEOUT_S] [--flag...]
Exit: 0 the value printed; 1 the page threw, timed out or made a request.
"""
import base64
import json
import os
import select
import subprocess
import sys
import tempfile
import time


def fail(msg):
    print("web_page: " + msg, file=sys.stderr)
    sys.exit(1)


class TimedOut(Exception):
    """The deadline passed with no answer (the page's promise never settled, or Chromium hung)."""


class Pipe:
    def __init__(self, browser, flags, profile, log):
        to_r, to_w = os.pipe()      # commands: we write, Chromium reads fd 3
        from_r, from_w = os.pipe()  # answers: Chromium writes fd 4
        def child():
            os.dup2(to_r, 3)
            os.dup2(from_w, 4)
        self.proc = subprocess.Popen([browser, "--remote-debugging-pipe", "--user-data-dir=" + profile] + flags,
                                     pass_fds=(3, 4), preexec_fn=child,
                                     stdout=subprocess.DEVNULL, stderr=log)
        os.close(to_r)
        os.close(from_w)
        self.w, self.r = to_w, from_r
        self.buf = b""
        self.next_id = 0
        self.requests = []

    def send(self, method, params=None, session=None):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            msg["sessionId"] = session
        os.write(self.w, json.dumps(msg).encode() + b"\0")
        return self.next_id

    def read(self, deadline):
        while b"\0" not in self.buf:
            left = deadline - time.time()
            # select, not a bare read: Chromium sends nothing while a page's promise is pending.
            if left <= 0 or not select.select([self.r], [], [], left)[0]:
                raise TimedOut()
            chunk = os.read(self.r, 1 << 16)
            if not chunk:
                fail("chromium closed the pipe")
            self.buf += chunk
        raw, self.buf = self.buf.split(b"\0", 1)
        msg = json.loads(raw)
        if msg.get("method") == "Network.requestWillBeSent":
            url = msg["params"]["request"]["url"]
            allowed = ("file:", "data:", "blob:") + ((os.environ["WEB_PAGE_ALLOW"],) if os.environ.get("WEB_PAGE_ALLOW") else ())
            if not url.startswith(allowed):
                self.requests.append(url)
        return msg

    def call(self, method, params, deadline, session=None, until=None):
        """Sends a command; returns its result (after the event `until`, if given)."""
        want = self.send(method, params, session)
        result, seen = None, until is None
        while result is None or not seen:
            msg = self.read(deadline)
            if msg.get("id") == want:
                if "error" in msg:
                    fail(method + ": " + json.dumps(msg["error"]))
                result = msg["result"]
            elif msg.get("method") == until:
                seen = True
        return result


def renderer_peaks_kb(root):
    """VmHWM of each renderer process under pid root (Linux /proc)."""
    parent, cmd = {}, {}
    for d in os.listdir("/proc"):
        if not d.isdigit():
            continue
        try:
            stat = open("/proc/%s/stat" % d).read()
            parent[int(d)] = int(stat[stat.rindex(")") + 2:].split()[1])
            cmd[int(d)] = open("/proc/%s/cmdline" % d, "rb").read()
        except (OSError, ValueError):
            continue
    peaks = []
    for pid in parent:
        up = pid
        while up in parent and up != root:
            up = parent[up]
        if up == root and b"--type=renderer" in cmd[pid]:
            for line in open("/proc/%d/status" % pid):
                if line.startswith("VmHWM:"):
                    peaks.append(int(line.split()[1]))
    return peaks


def set_file(p, spec, deadline, s):
    """WEB_PAGE_FILE: SELECTOR=PATH into that file input."""
    selector, path = spec.split("=", 1)
    root = p.call("DOM.getDocument", {}, deadline, s)["root"]["nodeId"]
    node = p.call("DOM.querySelector", {"nodeId": root, "selector": selector}, deadline, s)["nodeId"]
    if not node:
        fail("no element " + selector)
    p.call("DOM.setFileInputFiles", {"nodeId": node, "files": [os.path.abspath(path)]}, deadline, s)


def where(p, s):
    """What a page that timed out shows: its window.dexmillTestAt (a test's
    step, when it sets one) and its status line."""
    try:
        r = p.call("Runtime.evaluate", {"expression": "JSON.stringify({at: window.dexmillTestAt, status: "
                                        "(document.getElementById('status') || {}).textContent})",
                                        "returnByValue": True}, time.time() + 10, s)
        return str(r["result"].get("value"))
    except TimedOut:
        return "(no answer)"


def write_profile(profile, path):
    """Self samples by function name, most first, as percentages."""
    names = {n["id"]: n["callFrame"]["functionName"] or "(anonymous " + n["callFrame"]["url"][-30:] + ")"
             for n in profile["nodes"]}
    count = {}
    for sample in profile.get("samples", []):
        count[names[sample]] = count.get(names[sample], 0) + 1
    total = max(1, sum(count.values()))
    with open(path, "w") as f:
        for name, n in sorted(count.items(), key=lambda kv: -kv[1]):
            f.write("%6.2f %% %7d  %s\n" % (100.0 * n / total, n, name))


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    flags = [a for a in sys.argv[1:] if a.startswith("--")]
    if len(args) < 3:
        fail("usage: web_page.py CHROMIUM URL EXPRESSION [TIMEOUT_S] [--flag...]")
    browser, url, expr = args[:3]
    deadline = time.time() + (float(args[3]) if len(args) > 3 else 120)
    log = open(os.environ.get("WEB_PAGE_LOG", os.devnull), "w")
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        p = Pipe(browser, flags, profile, log)
        try:
            target = p.call("Target.createTarget", {"url": "about:blank"}, deadline)["targetId"]
            s = p.call("Target.attachToTarget", {"targetId": target, "flatten": True}, deadline)["sessionId"]
            p.call("Network.enable", {}, deadline, s)
            p.call("Page.enable", {}, deadline, s)
            w, h = (int(v) for v in os.environ.get("WEB_PAGE_SIZE", "1000x620").split("x"))
            p.call("Emulation.setDeviceMetricsOverride",
                   {"width": w, "height": h, "deviceScaleFactor": 1, "mobile": False}, deadline, s)
            p.call("Page.navigate", {"url": url}, deadline, s, until="Page.loadEventFired")
            if os.environ.get("WEB_PAGE_FILE"):
                set_file(p, os.environ["WEB_PAGE_FILE"], deadline, s)
            prof = os.environ.get("WEB_PAGE_PROFILE")
            if prof:
                p.call("Profiler.enable", {}, deadline, s)
                p.call("Profiler.setSamplingInterval", {"interval": 100}, deadline, s)
                p.call("Profiler.start", {}, deadline, s)
            try:
                r = p.call("Runtime.evaluate", {"expression": expr, "awaitPromise": True, "returnByValue": True},
                           deadline, s)
            except TimedOut:
                fail("timed out; the page then: " + where(p, s))
            if prof:
                write_profile(p.call("Profiler.stop", {}, deadline, s)["profile"], prof)
            if os.environ.get("WEB_PAGE_MEMORY"):
                with open(os.environ["WEB_PAGE_MEMORY"], "w") as f:
                    f.write(" ".join(str(k) for k in renderer_peaks_kb(p.proc.pid)) + "\n")
            shot = os.environ.get("WEB_PAGE_SCREENSHOT")
            if shot:
                png = p.call("Page.captureScreenshot", {"format": "png"}, deadline, s)["data"]
                with open(shot, "wb") as f:
                    f.write(base64.b64decode(png))
        except TimedOut:
            fail("timed out waiting for Chromium")
        finally:
            # Browser.close ends every process of it (a kill leaves its children writing the profile).
            try:
                p.send("Browser.close")
                p.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                p.proc.kill()
                p.proc.wait()
    if "exceptionDetails" in r:
        d = r["exceptionDetails"]
        fail("the page threw: " + d.get("exception", {}).get("description", d.get("text", "?")))
    if p.requests:
        fail("the page made requests: " + " ".join(p.requests))
    print(json.dumps(r["result"].get("value")))


main()
