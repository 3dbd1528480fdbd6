// The browser's figures for docs/web.md: frames per second of the app in headless Chromium
// (WebGL2 on SwiftShader, a software GPU) with the time a frame spends simulating and drawing,
// and ns per spring-step of the core compiled to WebAssembly (bench.html). Prints key=value lines
// that scripts/web-bench.sh puts beside the native figures.
//   node bench/web/web_bench.cjs
"use strict";
const path = require("path");
const { serve, launch, openApp, status } = require("../../tests/web/page.cjs");

const site = path.resolve(__dirname, "../../build-web");
const build = path.resolve(__dirname, "../../build-wasm");  // its bench page, served as /_build/
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

const pages = [
  ["rope", "scene=rope"],
  ["cloth_24", "scene=cloth"],
  ["cloth_64", "scene=cloth&set=cloth.width%3D64&set=cloth.height%3D64"],
];
const steps = (process.env.SPRINGLAB_BENCH_STEPS || "").split(";").filter(Boolean);

(async () => {
  const { server, base } = await serve(site, build);
  const browser = await launch();
  for (const [name, link] of pages) {
    const page = await openApp(browser, base, link);
    await sleep(3000);  // past the first analyses and the JIT's warm-up
    const first = await status(page), t0 = Date.now();
    let sim = 0, draw = 0, frame = 0, n = 0;
    while (Date.now() - t0 < 5000) {
      await sleep(250);
      const s = await status(page);
      sim += s.sim_ms;
      draw += s.draw_ms;
      frame += s.frame_ms;
      n++;
    }
    const last = await status(page);
    const fps = (last.frames - first.frames) / ((Date.now() - t0) / 1000);
    console.log(`${name}_fps=${fps.toFixed(1)} ${name}_frame_ms=${(frame / n).toFixed(2)} ` +
                `${name}_sim_ms=${(sim / n).toFixed(2)} ${name}_draw_ms=${(draw / n).toFixed(2)} ` +
                `${name}_realtime=${last.realtime.toFixed(2)}`);
    await page.close();
  }
  for (const args of steps) {
    const page = await browser.newPage();
    await page.goto(`${base}/_build/bench/bench.html?args=${encodeURIComponent(args)}`);
    await page.waitForFunction("window.benchResult !== undefined", { timeout: 600000, polling: 200 });
    const log = await page.evaluate(() => window.benchLog);
    const ns = log.map((l) => l.match(/^ns_per_spring_step=(.*)$/)).filter(Boolean)[0];
    console.log(`wasm ${args}: ns_per_spring_step=${ns ? ns[1] : "failed: " + log.join(" ")}`);
    await page.close();
  }
  await browser.close();
  server.close();
})();
