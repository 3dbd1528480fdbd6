// What the browser tests share: a static server for build-web/ on loopback, Debian's Chromium
// through puppeteer-core (headless, WebGL2 on SwiftShader), the app's page opened at a link and
// driven, and images compared with a golden one (with a tolerance, and a diff image on failure).
"use strict";
const fs = require("fs");
const http = require("http");
const path = require("path");
const puppeteer = require("puppeteer-core");

// puppeteer-core 22 numbers each CDP session's commands on their own, and Chromium answers a command
// sent to a session that has just closed without the session's id ("Session with given id not
// found."): puppeteer then takes it for the browser connection's own command of the same number, and
// that command fails (a newPage did so: "Protocol error (Target.createTarget): Session with given id
// not found"; crbug.com/1463459, fixed in puppeteer 24 by numbering all commands together, #13910).
// Pages with a service worker (sw.js) make it frequent: their worker attaches to them and is detached
// as they close. The connection's own commands name no session, so such an answer is never theirs:
// it is dropped here (the closed session's commands have failed already, as it closed).
try {
  const { Connection } = require("puppeteer-core/internal/cdp/Connection.js");
  const onMessage = Connection.prototype.onMessage;
  Connection.prototype.onMessage = function (message) {
    if (message.includes('"code":-32001')) {
      const object = JSON.parse(message);
      if (!object.sessionId && object.id !== undefined && /Session with given id not found/.test(object.error?.message))
        return Promise.resolve();
    }
    return onMessage.call(this, message);
  };
} catch (e) {
  // (Another puppeteer: without the fix.)
}

const types = {
  ".html": "text/html", ".js": "text/javascript", ".wasm": "application/wasm", ".data": "application/octet-stream",
  ".png": "image/png", ".json": "application/json", ".webmanifest": "application/manifest+json",
};

// Serves `dir` on 127.0.0.1 at a free port, and the build tree `build` (if given) under /_build/
// (the core's tests' and benchmarks' pages); resolves to { server, base }.
function serve(dir, build) {
  const server = http.createServer((req, res) => {
    const at = decodeURIComponent(new URL(req.url, "http://x").pathname);
    const root = build && at.startsWith("/_build/") ? build : dir;
    const file = path.join(root, root === dir ? at : at.slice("/_build".length));
    if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404);
      res.end();
      return;
    }
    res.writeHead(200, { "Content-Type": types[path.extname(file)] || "application/octet-stream" });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, "127.0.0.1", () =>
    resolve({ server, base: `http://127.0.0.1:${server.address().port}` })));
}

// The host name an insecure origin is tried at (mapped to loopback): not localhost nor 127.0.0.1, so
// a page there is not a secure context and has no service worker.
const insecureHost = "springlab-insecure.test";

function launch() {
  return puppeteer.launch({
    executablePath: process.env.CHROMIUM || "/usr/bin/chromium",
    headless: "new",
    // English whatever the machine's locale: a check that wants another language says so (openApp).
    args: ["--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--window-size=1280,720",
           "--disable-dev-shm-usage", "--lang=en-US", `--host-resolver-rules=MAP ${insecureHost} 127.0.0.1`],
  });
}

// Every console error and uncaught exception of every page, for the final check.
const consoleErrors = [];

// Opens the app at `fragment` (without '#') and waits for its first frames. `browser` may be a
// browser context; `query` goes after index.html ('?...'); `offline` cuts the page's network first;
// `language`: the browser's (navigator.language), as a reader's browser set to it reports it.
async function openApp(browser, base, fragment, { width = 1280, height = 720, scale = 1, touch = false, query = "",
                                                  offline = false, language } = {}) {
  const page = await browser.newPage();
  if (language)
    await page.evaluateOnNewDocument((l) => Object.defineProperty(navigator, "language", { get: () => l }), language);
  await page.setViewport({ width, height, deviceScaleFactor: scale, hasTouch: touch });
  page.on("console", (m) => { if (m.type() === "error") consoleErrors.push(`${fragment}: ${m.text()}`); });
  page.on("pageerror", (e) => consoleErrors.push(`${fragment}: ${e.message}`));
  if (offline) await page.setOfflineMode(true);
  await page.goto(`${base}/index.html${query}${fragment ? "#" + fragment : ""}`);
  await page.waitForFunction("window.springlabReady === true", { timeout: 60000 });
  await waitFrames(page, 5);
  return page;
}

async function status(page) {
  return JSON.parse(await page.evaluate(() => Module.ccall("springlab_status", "string", [], [])));
}

async function waitFrames(page, n) {
  const start = (await status(page)).frames;
  await page.waitForFunction((s, k) => JSON.parse(Module.ccall("springlab_status", "string", [], [])).frames >= s + k,
                             { timeout: 30000 }, start, n);
}

// A key as the app sees it: held for two frames (the app reads the keyboard once a frame).
async function key(page, name) {
  await page.focus("#canvas");
  await page.keyboard.down(name);
  await waitFrames(page, 2);
  await page.keyboard.up(name);
  await waitFrames(page, 2);
}

// Paused at the scene's start: the same picture every time (the clock shown is the scene's).
async function pauseAtStart(page) {
  if (!(await status(page)).paused) await key(page, "Space");
  await key(page, "KeyR");
  await waitFrames(page, 3);
}

// Compares two PNG buffers in a browser page (a 2D canvas decodes them): the share of pixels whose
// channels differ by more than `threshold`, and a diff image (differing pixels in red). With
// `region` ([x, y, w, h], where the scene is drawn) also the worst window's score there, as the
// native golden test judges (tests/golden/golden_test.cpp): square windows of side height * 24 /
// 270 overlapping by half, each scored by its differing pixels over its drawn ones (off the
// background, the golden's most common colour, in either image, or differing; at least a tenth of
// the window): `windowScore`, and the worst window's place `window`.
async function compareImages(browser, a, b, threshold = 40, region = null) {
  const page = await browser.newPage();
  const result = await page.evaluate(async (a64, b64, threshold, region) => {
    const load = async (b64) => {
      const img = new Image();
      img.src = "data:image/png;base64," + b64;
      await img.decode();
      const c = document.createElement("canvas");
      c.width = img.width;
      c.height = img.height;
      const g = c.getContext("2d");
      g.drawImage(img, 0, 0);
      return { w: img.width, h: img.height, data: g.getImageData(0, 0, img.width, img.height).data, c, g };
    };
    const A = await load(a64), B = await load(b64);
    if (A.w !== B.w || A.h !== B.h) return { sizeMismatch: `${A.w}x${A.h} against ${B.w}x${B.h}`, fraction: 1 };
    const diff = A.g.getImageData(0, 0, A.w, A.h);
    let differing = 0;
    for (let i = 0; i < A.data.length; i += 4) {
      const d = Math.max(Math.abs(A.data[i] - B.data[i]), Math.abs(A.data[i + 1] - B.data[i + 1]),
                         Math.abs(A.data[i + 2] - B.data[i + 2]));
      const grey = (A.data[i] + A.data[i + 1] + A.data[i + 2]) / 12;
      diff.data[i] = d > threshold ? 255 : grey;
      diff.data[i + 1] = d > threshold ? 0 : grey;
      diff.data[i + 2] = d > threshold ? 0 : grey;
      diff.data[i + 3] = 255;
      if (d > threshold) differing++;
    }
    let windowScore = 0, window = null;
    if (region) {
      const [rx, ry, rw, rh] = region.map(Math.round);
      const counts = new Map();
      for (let y = ry; y < ry + rh; y += 4)
        for (let x = rx; x < rx + rw; x += 4) {
          const i = 4 * (y * A.w + x), c = (A.data[i] << 16) | (A.data[i + 1] << 8) | A.data[i + 2];
          counts.set(c, (counts.get(c) || 0) + 1);
        }
      let bg = 0, most = -1;
      for (const [c, n] of counts) if (n > most) { bg = c; most = n; }
      const off = (D, i) => Math.max(Math.abs(D[i] - (bg >> 16 & 255)), Math.abs(D[i + 1] - (bg >> 8 & 255)),
                                     Math.abs(D[i + 2] - (bg & 255))) > threshold;
      const side = Math.max(8, Math.min(Math.round(A.h * 24 / 270), rw, rh));
      const starts = (from, to) => {
        const s = [];
        for (let v = from; ; v += side / 2) {
          s.push(Math.min(v, to - side));
          if (v + side >= to) break;
        }
        return s;
      };
      for (const wy of starts(ry, ry + rh))
        for (const wx of starts(rx, rx + rw)) {
          let differ = 0, drawn = 0;
          for (let y = wy; y < wy + side; y++)
            for (let x = wx; x < wx + side; x++) {
              const i = 4 * (y * A.w + x);
              const d = diff.data[i] === 255 && diff.data[i + 1] === 0;  // marked differing above
              differ += d;
              drawn += d || off(A.data, i) || off(B.data, i);
            }
          const score = differ / Math.max(drawn, 0.1 * side * side);
          if (score > windowScore) { windowScore = score; window = [wx, wy, side, differ, drawn]; }
        }
    }
    A.g.putImageData(diff, 0, 0);
    return { fraction: differing / (A.w * A.h), windowScore, window, diff: A.c.toDataURL("image/png").split(",")[1] };
  }, a.toString("base64"), b.toString("base64"), threshold, region);
  await page.close();
  if (result.diff) result.diff = Buffer.from(result.diff, "base64");
  return result;
}

// Pixels of a PNG screenshot as RGBA rows, decoded by the browser.
async function pixels(browser, png) {
  const page = await browser.newPage();
  const out = await page.evaluate(async (b64) => {
    const img = new Image();
    img.src = "data:image/png;base64," + b64;
    await img.decode();
    const c = document.createElement("canvas");
    c.width = img.width;
    c.height = img.height;
    const g = c.getContext("2d");
    g.drawImage(img, 0, 0);
    return { w: img.width, h: img.height, data: Array.from(g.getImageData(0, 0, img.width, img.height).data) };
  }, png.toString("base64"));
  await page.close();
  return out;
}

module.exports = { serve, launch, insecureHost, openApp, status, waitFrames, key, pauseAtStart, compareImages, pixels, consoleErrors };
