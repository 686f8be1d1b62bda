// Drives the viewer page in headless Chromium (puppeteer-core) and checks what a person sees
// and does: usage: node viewer_browser.js CHROMIUM PAGE.html CHECKS.json SCREENSHOT_DIR
// CHECKS.json: {"poses": {"driver": 0, "s": S, "parts": {id: [16 column-major numbers]}},
//               "drag": {"part": ID, "turns": T, "follower": ID, "axis": [x,y,z],
//                        "degrees": D}, "held": ID, "stop": {"part": ID, "turns": T,
//                        "meets": [ID, ID]}, "mouse": {"part": ID, "pixels": P,
//                        "follower": ID, "axis": [x,y,z], "degrees": D},
//               "graph": {"nodes": N, "edges": E},
//               "step": {"part": ID, "obstacle": ID or "the pin through HOLES",
//                        "red_pins": N (0 if absent), "shot": FILE (viewer_step.png)},
//               "subassembly": {"part": ID, "apart": ID, "shot": FILE, "alone": [ID, ...] (shown
//                               at the end of `apart`'s step or attempt)},
//               "cache": {"part": ID, "turns": T},
//               "run": {"driver": 0, "s": S, "meets": [ID, ID]}}, every entry optional
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
  // Generous: swiftshader on a 2-core machine busy with other tests can take 20 s to start.
  await page.waitForFunction(() => window.mechanist !== undefined, { timeout: 90000 });
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
  // The canvas takes the view's size once its layout settles (a ResizeObserver); under load
  // that can be after the page's script has run.
  try {
    await page.waitForFunction(() => {
      const canvas = document.querySelector("canvas");
      const gl = canvas && (canvas.getContext("webgl2") || canvas.getContext("webgl"));
      return gl && gl.drawingBufferWidth > 0 && gl.drawingBufferHeight > 0;
    }, { timeout: 30000 });
  } catch (e) {
    fail("the 3D view's canvas has no size: " + e.message);
  }
  // Then a frame drawn at that size (the page draws on the next animation frame).
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
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
  if (checks.run) {
    const r = checks.run;
    const met = await page.evaluate((r) => window.mechanist.setDriver(r.driver, r.s), r);
    const want = JSON.stringify(r.meets.slice().sort());
    if (!met.some((c) => JSON.stringify(c.parts.slice().sort()) === want)) {
      fail("running driver " + r.driver + " to " + r.s + " meets " + JSON.stringify(met) +
           ", not " + r.meets);
    }
    console.log("ok running driver " + r.driver + " to " + r.s + " shows its clash: " +
                met.map((c) => c.parts.join(" meets ") + " at " + c.at.toFixed(3)).join("; "));
    await shot("viewer_run.png");
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
  if (checks.step) {
    // The assembly stepper: the step that inserts the part starts outside, and, blocked,
    // ends at its first contact with the obstacle, later steps' parts hidden.
    const t = checks.step;
    const result = await page.evaluate((t) => {
      const m = window.mechanist;
      const k = m.data.assembly.steps.findIndex((st) => m.data.parts[st.part].id === t.part);
      if (k < 0) return null;
      const start = m.assemblyStep(k, 0);
      const outside = m.pose(t.part);
      const end = m.assemblyStep(k, 1);
      return { start, end, outside, inside: m.pose(t.part),
               later: m.data.assembly.steps.slice(k + 1).map((st) => m.data.parts[st.part].id) };
    }, t);
    if (!result) fail("no assembly step inserts " + t.part);
    if (result.end.clear || result.end.obstacle !== t.obstacle) {
      fail("the step of " + t.part + " shows " + JSON.stringify(result.end) + ", not the obstacle " +
           t.obstacle);
    }
    // A pin the file leaves out that stops the step shows in place, drawn in red.
    if (result.end.red_pins !== (t.red_pins || 0)) {
      fail("the step of " + t.part + " draws " + result.end.red_pins + " pins in red, not " +
           (t.red_pins || 0));
    }
    const moved = Math.hypot(...[12, 13, 14].map((k) => result.outside[k] - result.inside[k]));
    if (!(moved > 1)) fail("the step of " + t.part + " does not move it in (" + moved + ")");
    for (const id of result.later) {
      if (!result.end.hidden.includes(id)) fail("a later step's part is shown: " + id);
    }
    console.log("ok the assembly step of " + t.part + " moves it " + moved.toFixed(2) +
                " and stops where it meets " + result.end.obstacle + " after " +
                result.end.at.toFixed(2) + ", " + result.end.hidden.length + " later parts hidden");
    await shot(t.shot || "viewer_step.png");
  }
  if (checks.pins) {
    // The pins the file leaves out: a step's pins show in place at its end, not before, and
    // its row in the list says how each goes in.
    const t = checks.pins;
    const result = await page.evaluate((t) => {
      const m = window.mechanist;
      const k = m.data.assembly.steps.findIndex((st) => m.data.parts[st.part].id === t.part);
      if (k < 0) return null;
      const before = m.assemblyStep(k, 0.5).pins;
      const after = m.assemblyStep(k, 1).pins;
      const row = document.querySelectorAll("#assembly-steps .row")[k];
      return { before, after, words: row.textContent, error: row.classList.contains("error") };
    }, t);
    if (!result) fail("no assembly step inserts " + t.part);
    if (result.before !== t.before || result.after !== t.after) {
      fail("the step of " + t.part + " shows " + result.before + " pins half way and " +
           result.after + " at its end, not " + t.before + " and " + t.after);
    }
    const words = [].concat(t.words);  // one or more pieces of the row, in order
    if (!words.length || words.some((w) => !w)) fail("no words to look for in the row");
    let at = 0;
    const inOrder = words.every((w) => {
      const found = result.words.indexOf(w, at);
      at = found + w.length;
      return found >= 0;
    });
    if (!inOrder || result.error !== t.error) {
      fail("the step's row reads '" + result.words + "' (error " + result.error + "), not '" +
           words.join(" ... ") + "' (error " + t.error + ")");
    }
    console.log("ok the step of " + t.part + " shows " + result.after + " pins at its end: " +
                result.words);
    await shot("viewer_pin.png");
  }
  if (checks.subassembly) {
    // A sub-assembly moves in as one, its parts together; a step (or attempt) that puts it
    // together apart shows its parts put together by then and nothing else.
    const t = checks.subassembly;
    const result = await page.evaluate((t) => {
      const m = window.mechanist;
      const steps = m.data.assembly.steps;
      const id = (p) => m.data.parts[p].id;
      const k = steps.findIndex((st) => st.subassembly && id(st.part) === t.part);
      const a = steps.findIndex((st) => st.apart_for === k && id(st.part) === t.apart);
      if (k < 0 || a < 0) return null;
      const moving = [steps[k].part].concat(steps[k].carried).map(id);
      m.assemblyStep(k, 0);
      const start = moving.map((p) => m.pose(p));
      m.assemblyStep(k, 1);
      const end = moving.map((p) => m.pose(p));
      const apart = m.assemblyStep(a, 1);
      const row = document.querySelectorAll("#assembly-steps .row")[a].textContent;
      return { moving, start, end, hidden: apart.hidden, row, all: m.data.parts.map((p) => p.id) };
    }, t);
    if (!result) fail("no sub-assembly step of " + t.part + " with " + t.apart + " apart for it");
    const shift = (i) => [12, 13, 14].map((c) => result.start[i][c] - result.end[i][c]);
    const first = shift(0);
    if (!(Math.hypot(...first) > 1)) fail("the sub-assembly of " + t.part + " does not move in");
    for (let i = 1; i < result.moving.length; ++i) {
      if (Math.hypot(...shift(i).map((v, c) => v - first[c])) > 1e-6) {
        fail(result.moving[i] + " does not move with " + t.part + " in its sub-assembly");
      }
    }
    const expected = result.all.filter((id) => !t.alone.includes(id)).sort();
    if (JSON.stringify([...result.hidden].sort()) !== JSON.stringify(expected)) {
      fail("putting " + t.apart + " in apart hides " + JSON.stringify(result.hidden) +
           ", not all but " + JSON.stringify(t.alone));
    }
    if (!/^\d+\. apart, into the sub-assembly of step /.test(result.row)) {
      fail("the apart row reads " + result.row);
    }
    console.log("ok the sub-assembly of " + t.part + " moves in as one (" +
                result.moving.join(" + ") + "); apart, " + t.apart + " is with " +
                t.alone.join(", ") + " only");
    await shot(t.shot || "viewer_subassembly.png");
  }
  if (checks.cache) {
    // A drag drawn from the cache of the still parts looks as when everything is redrawn.
    const c = checks.cache;
    const result = await page.evaluate((c) => {
      const m = window.mechanist;
      const pixels = () => {
        const gl = document.querySelector("canvas").getContext("webgl");
        const out = new Uint8Array(gl.drawingBufferWidth * gl.drawingBufferHeight * 4);
        gl.readPixels(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight, gl.RGBA,
                      gl.UNSIGNED_BYTE, out);
        return out;
      };
      if (!m.drag(c.part, c.turns)) return null;
      const used = m.setCache(true);
      const cached = pixels();
      m.setCache(false);
      const full = pixels();
      let differ = 0, drawn = 0;
      for (let i = 0; i < full.length; i += 4) {
        drawn += full[i] < 250 || full[i + 1] < 250 || full[i + 2] < 250;
        differ += Math.max(...[0, 1, 2].map((k) => Math.abs(full[i + k] - cached[i + k]))) > 24;
      }
      return { used, differ: differ / drawn };
    }, c);
    if (!result) fail("cannot drag " + c.part);
    if (!result.used) fail("the page draws no cache here (WEBGL_depth_texture, EXT_frag_depth)");
    if (!(result.differ < 0.01)) {
      fail("a drag drawn from the cache differs from a full redraw in " +
           (100 * result.differ).toFixed(2) + "% of the drawn pixels");
    }
    console.log("ok a drag drawn from the cache of still parts matches a full redraw (" +
                (100 * result.differ).toFixed(3) + "% of the drawn pixels differ)");
  }
  if (errors.length) fail("console errors: " + errors.join(" | "));
  await browser.close();
  console.log("all checks passed");
})().catch((e) => fail(String(e)));
