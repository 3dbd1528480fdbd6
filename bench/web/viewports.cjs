// The app at a phone's, a tablet's and a laptop's sizes (docs/web.md, "Screen sizes"): for each
// viewport, the time from the page's start to the app's first frame (cold: a fresh profile, the
// files from loopback; the median of 3 pages), the frames a second it then shows (after 2 s, over 5 s) with the time a
// frame spends simulating and drawing, and the layout (window.springlabLayout): the scene's
// rectangle and the panels shown, in CSS pixels. Nothing is asserted. About a minute and a half.
//   scripts/web.sh && tests/web/node.sh bench/web/viewports.cjs [LINK]
"use strict";
const path = require("path");
const { serve, launch, openApp, status, consoleErrors } = require("../../tests/web/page.cjs");

const site = path.resolve(__dirname, "../../build-web");
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const link = process.argv[2] || "";

const viewports = [
  { name: "phone, portrait", width: 390, height: 844, scale: 3, touch: true },
  { name: "phone, landscape", width: 844, height: 390, scale: 3, touch: true },
  { name: "tablet, portrait", width: 768, height: 1024, scale: 1, touch: false },
  { name: "laptop", width: 1024, height: 640, scale: 1, touch: false },
  { name: "the tests' page", width: 1280, height: 720, scale: 1, touch: false },
];

(async () => {
  const { server, base } = await serve(site);
  const browser = await launch();
  console.log(`link: index.html${link ? "#" + link : ""}`);
  console.log("| viewport (CSS px, pixel ratio) | canvas px | first frame (ms) | frames/s | sim / draw (ms) | scene [x, y, w, h] | panels |");
  console.log("|---|---|---|---|---|---|---|");
  for (const v of viewports) {
    const firsts = [];
    let context, page;
    for (let k = 0; k < 3; k++) {
      if (page) {
        await page.close();
        await context.close();
      }
      context = await browser.createBrowserContext();
      page = await openApp(context, base, link, v);
      firsts.push(await page.evaluate(() => window.springlabReadyAt));
    }
    const first = firsts.sort((a, b) => a - b)[1];
    await sleep(2000);
    const s0 = await status(page), t0 = Date.now();
    let sim = 0, draw = 0, n = 0;
    while (Date.now() - t0 < 5000) {
      await sleep(250);
      const s = await status(page);
      sim += s.sim_ms;
      draw += s.draw_ms;
      n++;
    }
    const s1 = await status(page);
    const fps = (s1.frames - s0.frames) / ((Date.now() - t0) / 1000);
    const l = await page.evaluate(() => window.springlabLayout());
    const r = (a) => `[${a.map((x) => Math.round(x)).join(", ")}]`;
    const panels = l.names.map((name, i) => `${name} ${r(l.panels[i])}`).join("; ");
    console.log(`| ${v.name}: ${v.width} x ${v.height}, ${v.scale}${v.touch ? ", touch" : ""} | ` +
                `${v.width * v.scale} x ${v.height * v.scale} | ${first.toFixed(0)} | ${fps.toFixed(1)} | ` +
                `${(sim / n).toFixed(1)} / ${(draw / n).toFixed(1)} | ${r(l.scene)} | ${panels} |`);
    await page.close();
    await context.close();
  }
  if (consoleErrors.length) console.log(`console errors: ${consoleErrors.join("\n")}`);
  await browser.close();
  server.close();
})();
