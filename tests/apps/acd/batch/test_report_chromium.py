"""acd report in headless Chromium: the page loads without console errors or failed loads, lists
every mesh of the batch, sorts by parts, and a click on a card's button opens the WebGL view,
whose canvas (screenshot through the DevTools protocol) shows the hulls in several colours.

Run by ctest (batch_report_chromium): test_report_chromium.py ACD CORPUS. Exits 77 (skipped, with
a message) only when Chromium is not installed; scripts/setup.sh installs it."""

import base64
import io
import json
import os
import re
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.request


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


class DevTools:
    """The smallest WebSocket client the DevTools protocol needs (RFC 6455: text frames, masked)."""

    def __init__(self, url):
        m = re.match(r"ws://([^/:]+):(\d+)(/.*)", url)
        self.sock = socket.create_connection((m.group(1), int(m.group(2))), timeout=60)
        key = base64.b64encode(os.urandom(16)).decode()
        self.sock.sendall(("GET %s HTTP/1.1\r\nHost: %s:%s\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                           "Sec-WebSocket-Key: %s\r\nSec-WebSocket-Version: 13\r\n\r\n"
                           % (m.group(3), m.group(1), m.group(2), key)).encode())
        reply = b""
        while b"\r\n\r\n" not in reply:
            reply += self.sock.recv(4096)
        assert b" 101 " in reply.split(b"\r\n")[0], reply
        self.buffer = reply.split(b"\r\n\r\n", 1)[1]
        self.next_id = 0
        self.events = []

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise ConnectionError("DevTools connection closed")
            self.buffer += chunk
        data, self.buffer = self.buffer[:n], self.buffer[n:]
        return data

    def _message(self):
        parts = b""
        while True:
            head = self._read(2)
            fin, opcode, length = head[0] & 0x80, head[0] & 0x0F, head[1] & 0x7F
            if length == 126:
                length = struct.unpack(">H", self._read(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", self._read(8))[0]
            payload = self._read(length)
            if opcode in (0x1, 0x0):
                parts += payload
                if fin:
                    return json.loads(parts)

    def call(self, method, **params):
        self.next_id += 1
        body = json.dumps({"id": self.next_id, "method": method, "params": params}).encode()
        mask = os.urandom(4)
        n = len(body)
        header = bytes([0x81]) + (bytes([0x80 | n]) if n < 126 else bytes([0x80 | 126]) + struct.pack(">H", n)
                                  if n < 65536 else bytes([0x80 | 127]) + struct.pack(">Q", n))
        self.sock.sendall(header + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(body)))
        while True:
            msg = self._message()
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    raise RuntimeError("%s: %s" % (method, msg["error"]))
                return msg["result"]
            self.events.append(msg)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            raise RuntimeError("%s: %s" % (expression, r["exceptionDetails"]))
        return r["result"].get("value")

    def wait_for(self, expression, seconds=30):
        end = time.time() + seconds
        while time.time() < end:
            if self.evaluate(expression):
                return True
            time.sleep(0.1)
        return False

    def click(self, selector):
        box = self.evaluate("(() => { const r = document.querySelector(%s).getBoundingClientRect();"
                            " return [r.x + r.width / 2, r.y + r.height / 2]; })()" % json.dumps(selector))
        for kind in ("mouseMoved", "mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=box[0], y=box[1], button="left", clickCount=1)

    def errors(self):
        found = []
        for e in self.events:
            method, p = e.get("method"), e.get("params", {})
            if method == "Runtime.exceptionThrown":
                found.append(p["exceptionDetails"].get("exception", {}).get("description") or p["exceptionDetails"]["text"])
            elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                found.append(" ".join(str(a.get("value", a.get("description"))) for a in p.get("args", [])))
            elif method == "Log.entryAdded" and p["entry"].get("level") == "error":
                found.append(p["entry"].get("text", "") + " " + p["entry"].get("url", ""))
        return found


def main(acd, corpus):
    browser = chromium()
    if browser is None:
        print("SKIPPED: Chromium is not installed (scripts/setup.sh installs it: apt-get install chromium)")
        return 77
    work = tempfile.mkdtemp(prefix="acd_report_")
    proc = None
    try:
        os.makedirs(os.path.join(work, "in"))
        for m in ("eight", "handle"):
            shutil.copy(os.path.join(corpus, m + ".off"), os.path.join(work, "in"))
        with open(os.path.join(work, "in", "garbage.off"), "w") as f:
            f.write("OFF\nnot a mesh\n")
        out = os.path.join(work, "out")
        done = subprocess.run([acd, "batch", os.path.join(work, "in"), "-o", out, "-t", "0.2", "--report", "-q"],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
        assert done.returncode == 7, done.stdout  # garbage.off is refused
        with open(os.path.join(out, "batch.jsonl")) as f:
            records = [json.loads(line) for line in f if line.strip()]
        names = sorted(r["name"] for r in records)

        proc = subprocess.Popen([browser, "--headless=new", "--no-sandbox", "--no-first-run", "--disable-extensions",
                                 "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1200,900",
                                 "--remote-debugging-port=0", "--user-data-dir=" + os.path.join(work, "profile"),
                                 "about:blank"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        url = None
        end = time.time() + 60
        while url is None and time.time() < end:
            line = proc.stderr.readline()
            if not line:
                break
            m = re.search(r"DevTools listening on (ws://\S+)", line)
            url = m and m.group(1)
        assert url, "Chromium did not start its DevTools endpoint"
        port = re.match(r"ws://[^:]+:(\d+)/", url).group(1)
        pages = json.load(urllib.request.urlopen("http://127.0.0.1:%s/json/list" % port))
        page = DevTools(next(p for p in pages if p["type"] == "page")["webSocketDebuggerUrl"])
        for domain in ("Runtime.enable", "Log.enable", "Page.enable"):
            page.call(domain)
        page.call("Page.navigate", url="file://" + os.path.join(out, "index.html"))
        assert page.wait_for("document.readyState === 'complete' && document.querySelectorAll('.card').length > 0")
        assert page.wait_for("Array.from(document.images).every(i => i.complete)")

        shown = page.evaluate("Array.from(document.querySelectorAll('.card')).map(c => c.dataset.name)")
        assert shown == names, (shown, names)
        pictures = page.evaluate("Array.from(document.images).filter(i => i.naturalWidth > 0).length")
        placeholders = page.evaluate("document.querySelectorAll('.placeholder').length")
        ok = [r["name"] for r in records if r["status"] == "ok"]
        assert pictures + placeholders == len(names), (pictures, placeholders)
        print("pictures: %d, placeholders: %d" % (pictures, placeholders))

        # Sorted by parts (ascending; no parts first; ties by name): the oracle is the JSONL.
        page.click("#controls button[data-key=parts]")
        by_parts = sorted(records, key=lambda r: (r["parts"] if r["parts"] is not None else -1, r["name"]))
        shown = page.evaluate("Array.from(document.querySelectorAll('.card')).map(c => c.dataset.name)")
        assert shown == [r["name"] for r in by_parts], (shown, by_parts)

        # A click on eight's button opens the 3D view: the canvas must show the hulls.
        page.click(".card[data-name=eight] button.view")
        assert page.wait_for("document.getElementById('viewer').classList.contains('open') && scene !== null")
        time.sleep(0.5)
        box = page.evaluate("(() => { const r = document.getElementById('viewer-canvas').getBoundingClientRect();"
                            " return [r.x, r.y, r.width, r.height]; })()")
        shot = page.call("Page.captureScreenshot", format="png",
                         clip={"x": box[0], "y": box[1], "width": box[2], "height": box[3], "scale": 1})
        from PIL import Image
        image = Image.open(io.BytesIO(base64.b64decode(shot["data"]))).convert("RGB")
        image.save(os.path.join(work, "viewer.png"))
        background = (237, 240, 242)
        pixels = list(image.getdata())
        drawn = [p for p in pixels if max(abs(p[k] - background[k]) for k in range(3)) > 30]
        colours = {(p[0] // 32, p[1] // 32, p[2] // 32) for p in drawn}
        share = len(drawn) / len(pixels)
        print("3D view: %.1f %% of the canvas drawn, %d colour cells" % (100 * share, len(colours)))
        assert share > 0.03, "the 3D view is (nearly) empty"
        assert len(colours) >= 4, "the hulls are not drawn in several colours"

        errors = page.errors()
        assert not errors, "console errors: %s" % errors
        print("OK: %d meshes listed, sorted, 3D view rendered, no console errors" % len(names))
        return 0
    finally:
        if proc is not None:
            proc.kill()
            proc.wait()
        if os.environ.get("ACD_KEEP_REPORT_TEST"):
            print("kept:", work)
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])))
