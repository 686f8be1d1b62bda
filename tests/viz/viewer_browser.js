// Drives the viewer page in headless Chromium (puppeteer-core) and checks what a person sees
// and does: usage: node viewer_browser.js CHROMIUM PAGE.html CHECKS.json SCREENSHOT_DIR
// CHECKS.json: {"poses": {"driver": 0, "s": S, "parts": {id: [16 column-major numbers]}},
//               "drag": {"part": ID, "turns": T, "follower": ID, "axis": [x,y,z],
//                        "degrees": D}, "held": ID, "stop": {"part": ID, "turns": T,
//                        "meets": [ID, ID]}, "mouse": {"part": ID, "pixels": P,
//                        "follower": ID, "axis": [x,y,z], "degrees": D},
//               "graph": {"nodes": N, "edges": E}}, every entry optional
// Prints one line per check and exits 1 at the first failure.
"use strict";
const fs = require("fs");
const path = require("path");
const puppeteer = require("puppeteer-core");

const [chromium, page_file, checks_file, shots] = process.argv.slice(2);
const checks = JSON.parse(fs.readFileSync(checks_file, "utf8"));

function fail(message) {
  console.log("FAIL " + message);
  process.exit(1);
}

(async () => {
  const browser = await puppeteer.launch({
    executablePath: chromium,
    headless: true,
    args: ["--no-sandbox", "--use-gl=swiftshader", "--enable-unsafe-swiftshader",
           "--window-size=1200,800"],
  });
  const page = await browser.newPage();
  await page.setViewport({ width: 1200, height: 800 });
  const errors = [], requests = [];
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("request", (r) => {
    const url = r.url();
    if (!url.startsWith("data:") && url !== "file://" + path.resolve(page_file)) requests.push(url);
  });
  await page.goto("file://" + path.resolve(page_file), { waitUntil: "load" });
  await page.waitForFunction(() => window.mechanist !== undefined, { timeout: 20000 });
  if (errors.length) fail("console errors: " + errors.join(" | "));
  if (requests.length) fail("network requests: " + requests.join(" "));
  console.log("ok loads with no console error and no network request");

  if (checks.graph) {
    const drawn = await page.evaluate(() => ({
      nodes: document.querySelectorAll("#graph .node").length,
      edges: document.querySelectorAll("#graph .edge").length,
    }));
    if (drawn.nodes !== checks.graph.nodes || drawn.edges !== checks.graph.edges) {
      fail("the pair graph draws " + JSON.stringify(drawn) + ", not " + JSON.stringify(checks.graph));
    }
    console.log("ok the pair graph draws " + drawn.nodes + " subassemblies and " + drawn.edges +
                " pairs between them");
  }

  const shot = async (name) => {
    const file = path.join(shots, name);
    await page.screenshot({ path: file });
    return fs.readFileSync(file);
  };
  const first = await shot("viewer_start.png");
  const pixels = await page.evaluate(() => {
    const canvas = document.querySelector("canvas");
    const gl = canvas.getContext("webgl2") || canvas.getContext("webgl");
    const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
    const data = new Uint8Array(w * h * 4);
    gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, data);
    let coloured = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (data[i] < 240 || data[i + 1] < 240 || data[i + 2] < 240) ++coloured;
    }
    return coloured / (w * h);
  });
  if (!(pixels > 0.002)) fail("the 3D view is blank (" + pixels + " of the pixels drawn)");
  console.log("ok the view shows the parts (" + (100 * pixels).toFixed(1) + "% of the pixels)");

  if (checks.poses) {
    const p = checks.poses;
    const worst = await page.evaluate((p) => {
      window.mechanist.setDriver(p.driver, p.s);
      let worst = 0;
      for (const [id, expected] of Object.entries(p.parts)) {
        const got = window.mechanist.pose(id);
        for (let k = 0; k < 16; ++k) worst = Math.max(worst, Math.abs(got[k] - expected[k]));
      }
      return worst;
    }, p);
    if (!(worst < 1e-6)) fail("driver poses differ from StateAt by " + worst);
    console.log("ok driver poses equal StateAt (largest difference " + worst.toExponential(1) + ")");
    const moved = await shot("viewer_driver.png");
    if (Buffer.compare(first, moved) === 0) fail("the picture did not change with the driver");
    console.log("ok the picture changes as the driver slider moves");
  }
  if (checks.drag) {
    const d = checks.drag;
    const turned = await page.evaluate((d) => {
      if (!window.mechanist.drag(d.part, d.turns)) return null;
      return window.mechanist.turned(d.follower, d.axis);
    }, d);
    if (turned === null) fail("cannot drag " + d.part);
    if (!(Math.abs(turned - d.degrees) < 1e-6)) {
      fail("dragging " + d.part + " turned " + d.follower + " by " + turned + " deg, not " + d.degrees);
    }
    console.log("ok dragging " + d.part + " by " + d.turns + " rev turns " + d.follower + " by " +
                turned.toFixed(6) + " deg");
    await shot("viewer_drag.png");
  }
  if (checks.mouse) {
    // Press on the part and move the mouse sideways, as a person would.
    const m = checks.mouse;
    await page.evaluate(() => window.mechanist.select(null));
    const [x, y] = await page.evaluate((id) => window.mechanist.screenPoint(id), m.part);
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let k = 1; k <= 10; ++k) await page.mouse.move(x + (m.pixels * k) / 10, y);
    await page.mouse.up();
    const turned = await page.evaluate((m) => window.mechanist.turned(m.follower, m.axis), m);
    if (!(Math.abs(Math.abs(turned) - m.degrees) < 0.01)) {
      fail("a mouse drag of " + m.part + " by " + m.pixels + " px turned " + m.follower + " by " +
           turned + " deg, not " + m.degrees);
    }
    console.log("ok a mouse drag of " + m.part + " by " + m.pixels + " px turns " + m.follower +
                " by " + turned.toFixed(3) + " deg");
    await shot("viewer_mouse.png");
  }
  if (checks.stop) {
    const t = checks.stop;
    const result = await page.evaluate((t) => window.mechanist.drag(t.part, t.turns), t);
    if (!result || !result.stop) fail("dragging " + t.part + " did not stop: " + JSON.stringify(result));
    if (JSON.stringify(result.stop.slice().sort()) !== JSON.stringify(t.meets.slice().sort())) {
      fail("dragging " + t.part + " stops where " + result.stop + " meet, not " + t.meets);
    }
    console.log("ok dragging " + t.part + " stops at " + (360 * result.at).toFixed(1) +
                " deg where " + result.stop.join(" and ") + " meet");
    await shot("viewer_stop.png");
  }
  if (checks.held) {
    const info = await page.evaluate((id) => {
      window.mechanist.select(id);
      return window.mechanist.dragInfo();
    }, checks.held);
    if (!/held by P\d+/.test(info)) fail("dragging " + checks.held + " says: " + info);
    // The pairs named are the fixed pairs that fasten it (tight bolts), not others.
    const named = await page.evaluate((info) => {
      const pairs = window.mechanist.data.pairs;
      return [...info.matchAll(/P(\d+)/g)].map((m) => pairs[Number(m[1]) - 1]);
    }, info);
    for (const p of named) {
      if (p.type !== "fixed") fail("a holding pair is not fixed: " + JSON.stringify(p));
    }
    console.log("ok a part held by tight bolts names the holding pairs: " + info);
  }
  if (errors.length) fail("console errors: " + errors.join(" | "));
  await browser.close();
  console.log("all checks passed");
})().catch((e) => fail(String(e)));
