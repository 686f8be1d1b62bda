// Viewer benchmark, part 2: loads a viewer page (from bench/viewer_bench) in headless Chromium
// and measures what a person waits for and sees: the time from navigation to the first frame
// drawn (best and median of RUNS loads), the frame rate while the view is orbited with the
// mouse (everything redrawn each frame), and the frame rate while a part is dragged with the
// mouse (its train following; the still parts come from the page's cache), against the same
// drag with the cache off.
// Usage: NODE_PATH=.../node_modules node viewer_bench.js CHROMIUM PAGE.html PART [RUNS = 3]
"use strict";
const path = require("path");
const puppeteer = require("puppeteer-core");

const [chromium, page_file, part, runs_arg] = process.argv.slice(2);
const runs = Number(runs_arg || 3);

// Frames the page draws during `ms` milliseconds while `act` runs, per second.
async function frameRate(page, ms, act) {
  const before = await page.evaluate(() => window.mechanist.framesDrawn());
  const start = Date.now();
  await act(start + ms);
  const frames = (await page.evaluate(() => window.mechanist.framesDrawn())) - before;
  return (1000 * frames) / (Date.now() - start);
}

// Moves the mouse from (x, y) back and forth sideways, button down, until `until`.
async function sweepMouse(page, x, y, until) {
  await page.mouse.move(x, y);
  await page.mouse.down();
  let dx = 0;
  while (Date.now() < until) {
    dx = (dx + 4) % 200;
    await page.mouse.move(x + dx, y);
  }
  await page.mouse.up();
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ["--no-sandbox", "--use-gl=swiftshader", "--enable-unsafe-swiftshader",
           "--window-size=1200,800"],
  });
  const loads = [];
  let page = null;
  for (let k = 0; k < runs; ++k) {
    if (page) await page.close();
    page = await browser.newPage();
    await page.setViewport({ width: 1200, height: 800 });
    const errors = [];
    page.on("pageerror", (e) => errors.push(String(e)));
    await page.goto("file://" + path.resolve(page_file), { waitUntil: "load", timeout: 120000 });
    await page.waitForFunction(() => window.mechanist !== undefined, { timeout: 120000 });
    if (errors.length) throw new Error(errors.join(" | "));
    loads.push(await page.evaluate(() => window.mechanist.loadedMs));
  }
  loads.sort((a, b) => a - b);
  console.log("load to first frame: best " + (loads[0] / 1000).toFixed(2) + " s, median " +
              (loads[Math.floor(loads.length / 2)] / 1000).toFixed(2) + " s over " + runs);
  const [x, y] = await page.evaluate((id) => window.mechanist.screenPoint(id), part);
  const dragging = await frameRate(page, 5000, (until) => sweepMouse(page, x, y, until));
  const turned = await page.evaluate((id) => window.mechanist.turned(id, [0, 0, 1]), part);
  console.log("frame rate, dragging " + part + ": " + dragging.toFixed(1) + " fps (it turned " +
              turned.toFixed(1) + " deg)");
  // The same drag with every part redrawn each frame (the page without its cache).
  await page.evaluate(() => window.mechanist.setCache(false));
  const uncached = await frameRate(page, 5000, (until) => sweepMouse(page, x, y, until));
  console.log("frame rate, dragging " + part + " without the cache: " + uncached.toFixed(1) +
              " fps (the cache draws " + (dragging / uncached).toFixed(1) + " times as many)");
  // Orbiting: pressing on empty space near the view's top edge turns the camera.
  const orbiting = await frameRate(page, 5000, (until) => sweepMouse(page, 500, 30, until));
  console.log("frame rate, orbiting: " + orbiting.toFixed(1) + " fps");
  await browser.close();
})().catch((e) => { console.log("FAIL " + e); process.exit(1); });
