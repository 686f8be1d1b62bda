#include "viz/viewer_template.h"

namespace mechanist {

// The page's script evaluates the paths C++ computed (PlanRun, Drag): the pose of part p at
// parameter s is At(s) * X_WP, At the product of the screws, each a translation along its axis
// after a turn about it (ScrewMotion::At).
const char* const kViewerTemplate = R"html(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>@TITLE@</title>
<style>
  html, body { margin: 0; height: 100%; font: 13px/1.35 sans-serif; color: #222; }
  #app { display: flex; height: 100%; }
  #panel { width: 380px; overflow-y: auto; padding: 8px 12px; box-sizing: border-box;
           border-right: 1px solid #ccc; background: #fafafa; }
  #view { flex: 1; position: relative; }
  #hover { position: absolute; left: 8px; top: 8px; padding: 2px 6px; background: #fffd;
           border: 1px solid #ccc; display: none; pointer-events: none; }
  h1 { font-size: 16px; margin: 4px 0 8px; }
  h2 { font-size: 13px; margin: 12px 0 4px; border-bottom: 1px solid #ddd; }
  .row { margin: 2px 0; cursor: pointer; }
  .row:hover, .row.on { background: #e4ecff; }
  .warning { color: #9a5b00; } .error { color: #b00000; } .info { color: #555; }
  .passed { color: #1a7a1a; } .failed { color: #b00000; }
  details { margin-left: 10px; } summary { cursor: pointer; }
  .row, summary, #drag-info { overflow-wrap: anywhere; }
  input[type=range] { width: 200px; vertical-align: middle; }
  button { font-size: 12px; }
  #drag-info { color: #333; }
</style>
</head>
<body>
<div id="app">
  <div id="panel">
    <h1 id="title"></h1>
    <div>
      <label><input type="checkbox" id="show-axes"> feature axes</label>
      <label><input type="checkbox" id="section"> section</label>
      <input type="range" id="section-at" min="0" max="1000" value="500">
      <button id="fit">fit</button>
    </div>
    <h2>Drivers</h2><div id="drivers"></div>
    <h2>Drag</h2>
    <div id="drag-info">Click a part, then turn or slide it here.</div>
    <div id="drag-controls" style="display:none">
      <select id="drag-mode"></select>
      <input type="range" id="drag" min="-1000" max="1000" value="0">
      <span id="drag-value"></span>
    </div>
    <h2>Assembly sequence</h2>
    <div id="assembly-summary"></div>
    <div id="assembly-controls" style="display:none">
      <button id="step-back">&lt; step</button>
      <button id="step-next">step &gt;</button>
      <button id="step-play">play</button>
      <button id="step-done">assembled</button>
    </div>
    <div id="assembly-steps"></div>
    <h2>Mobility</h2><div id="mobility"></div>
    <h2>Clashes and gaps</h2><div id="clashes"></div><div id="gaps"></div>
    <h2>Expectations</h2><div id="expectations"></div>
    <h2>Parts</h2><div id="parts"></div>
    <h2>Subassemblies</h2><div id="subassemblies"></div>
    <h2>Pair graph</h2><div id="graph"></div>
    <h2>Pairs</h2><div id="pairs"></div>
    <h2>Diagnostics</h2><div id="diagnostics"></div>
  </div>
  <div id="view"><div id="hover"></div></div>
</div>
<script>@THREE@</script>
<script>@ORBIT@</script>
<script type="application/json" id="mechanist-data">@DATA@</script>
<script>
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("mechanist-data").textContent);
  const $ = (id) => document.getElementById(id);
  const text = (tag, content, cls) => {
    const e = document.createElement(tag);
    e.textContent = content;
    if (cls) e.className = cls;
    return e;
  };

  // ---- scene ----
  const view = $("view");
  // A large scene is drawn without multisampling (five times faster in software) and from a
  // cache of its still parts while parts move (below).
  const kLargeTriangles = 200000;
  let triangles = 0;
  for (const p of data.parts) if (p.mesh >= 0) triangles += data.meshes[p.mesh].triangles;
  const large = triangles > kLargeTriangles;
  const renderer = new THREE.WebGLRenderer({ antialias: !large, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.localClippingEnabled = true;
  view.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x777777, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(1, -1.5, 2);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 1e6);
  camera.up.set(0, 0, 1);
  const controls = new THREE.OrbitControls(camera, renderer.domElement);

  // ---- drawing: a large scene redraws only what moves ----
  // Software rendering (headless browsers, weak GPUs) takes a quarter of a second a frame for a
  // million triangles. So in a large scene, while parts move (a drag, a driver, an assembly
  // step), the still parts are drawn once into a colour and depth cache, and each frame copies
  // the cache (its depth too) and draws only the moving parts over it. The cache is redrawn
  // when anything about the still parts changes (`changed`: the camera, colours, visibility,
  // the section, the axes, the size) or the set of moving parts does.
  let stillVersion = 0, dirty = true;
  function changed() { ++stillVersion; dirty = true; }
  controls.addEventListener("change", changed);
  const canCache = !!(renderer.extensions.get("WEBGL_depth_texture") &&
                      renderer.extensions.get("EXT_frag_depth"));
  const cache = { on: large, target: null, drawn: "", scene: new THREE.Scene(),
                  camera: new THREE.OrthographicCamera(-1, 1, 1, -1, 0, 1) };
  const copy = new THREE.ShaderMaterial({
    uniforms: { color: { value: null }, depth: { value: null } },
    vertexShader: "varying vec2 at;\n" +
      "void main() { at = uv; gl_Position = vec4(position.xy, 0.0, 1.0); }",
    fragmentShader: "uniform sampler2D color;\nuniform sampler2D depth;\nvarying vec2 at;\n" +
      "void main() {\n  gl_FragColor = texture2D(color, at);\n" +
      "  gl_FragDepthEXT = texture2D(depth, at).x;\n}",
    depthTest: true, depthWrite: true, depthFunc: THREE.AlwaysDepth,
  });
  copy.extensions.fragDepth = true;
  cache.scene.add(new THREE.Mesh(new THREE.PlaneBufferGeometry(2, 2), copy));
  const setCacheSize = (w, h) => {
    if (!cache.target) {
      cache.target = new THREE.WebGLRenderTarget(w, h);
      cache.target.depthTexture = new THREE.DepthTexture(w, h);
      cache.target.depthTexture.type = THREE.UnsignedIntType;
      copy.uniforms.color.value = cache.target.texture;
      copy.uniforms.depth.value = cache.target.depthTexture;
    }
    cache.target.setSize(w, h);
  };
  let framesDrawn = 0;
  const draw = () => {
    ++framesDrawn;
    const moving = Object.keys(state.paths);
    if (!cache.on || !canCache || moving.length === 0) {
      renderer.render(scene, camera);
      return;
    }
    const movingSet = new Set(moving.map(Number));
    const shown = parts.map((part) => part.group.visible);
    const key = stillVersion + ":" + moving.join(",");
    if (cache.drawn !== key) {
      // The still parts only: the markers and gaps are few triangles, drawn every frame.
      const others = scene.children.filter((o) => !o.isLight && !parts.some((q) => q.group === o));
      const othersShown = others.map((o) => o.visible);
      others.forEach((o) => { o.visible = false; });
      parts.forEach((part, p) => { part.group.visible = shown[p] && !movingSet.has(p); });
      renderer.setRenderTarget(cache.target);
      renderer.render(scene, camera);
      renderer.setRenderTarget(null);
      others.forEach((o, k) => { o.visible = othersShown[k]; });
      cache.drawn = key;
    }
    renderer.render(cache.scene, cache.camera);
    parts.forEach((part, p) => { part.group.visible = shown[p] && movingSet.has(p); });
    const background = scene.background;
    scene.background = null;
    renderer.autoClear = false;
    renderer.render(scene, camera);
    renderer.autoClear = true;
    scene.background = background;
    parts.forEach((part, p) => { part.group.visible = shown[p]; });
  };

  const decode = (b64, Type) => {
    const bin = atob(b64);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; ++i) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer);
  };
  // Meshes come quantised: a coordinate is min + q * step, q a 16-bit step count.
  const geometries = data.meshes.map((m) => {
    const q = decode(m.positions, Uint16Array);
    const xyz = new Float32Array(q.length);
    for (let i = 0; i < q.length; ++i) xyz[i] = m.min[i % 3] + q[i] * m.step[i % 3];
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(xyz, 3));
    g.setIndex(new THREE.BufferAttribute(
      decode(m.indices, m.index_bytes === 2 ? Uint16Array : Uint32Array), 1));
    g.computeVertexNormals();
    return g;
  });
  const section = new THREE.Plane(new THREE.Vector3(-1, 0, 0), 0);
  const clipping = [];
  const parts = data.parts.map((p, index) => {
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    const base = new THREE.Matrix4().fromArray(p.X_WP);
    group.matrix.copy(base);
    const color = new THREE.Color(p.color[0], p.color[1], p.color[2]);
    const material = new THREE.MeshStandardMaterial({
      color, metalness: 0.1, roughness: 0.7, side: THREE.DoubleSide, flatShading: true,
      clippingPlanes: clipping });
    if (p.mesh >= 0) {
      const mesh = new THREE.Mesh(geometries[p.mesh], material);
      mesh.userData.part = index;
      group.add(mesh);
    }
    // A features-only part is drawn by its lines, in its subassembly's colour.
    const lineMaterial = new THREE.LineBasicMaterial({ color: p.mesh < 0 ? color : 0x222222 });
    const axes = new THREE.Group();
    for (const line of p.lines) {
      const g = new THREE.BufferGeometry().setFromPoints(
        line.map((q) => new THREE.Vector3(q[0], q[1], q[2])));
      axes.add(new THREE.Line(g, lineMaterial));
    }
    axes.visible = p.mesh < 0;  // a features-only part is drawn by its feature lines
    group.add(axes);
    scene.add(group);
    return { group, base, material, color, axes, sketch: p.mesh < 0 };
  });

  // ---- motion: the pose after s is At(s) * X_WP ----
  const screwAt = (screws, s) => {
    const D = new THREE.Matrix4();
    for (const m of screws) {
      const axis = new THREE.Vector3(m.axis[0], m.axis[1], m.axis[2]);
      const point = new THREE.Vector3(m.point[0], m.point[1], m.point[2]);
      const turn = new THREE.Matrix4().makeTranslation(point.x, point.y, point.z)
        .multiply(new THREE.Matrix4().makeRotationAxis(axis, 2 * Math.PI * m.turns * s))
        .multiply(new THREE.Matrix4().makeTranslation(-point.x, -point.y, -point.z));
      const slide = new THREE.Matrix4().makeTranslation(
        axis.x * m.travel * s, axis.y * m.travel * s, axis.z * m.travel * s);
      D.multiply(slide.multiply(turn));
    }
    return D;
  };
  // The motion shown: a driver's run or a part's drag, at parameter s.
  const state = { paths: {}, s: 0, driver: null, drag: null };
  const update = () => {
    parts.forEach((part, p) => {
      const screws = state.paths[p];
      part.group.matrix.copy(screws ? screwAt(screws, state.s).multiply(part.base) : part.base);
      part.group.matrixWorldNeedsUpdate = true;
    });
  };
  const show = (paths, s) => { state.paths = paths || {}; state.s = s; update(); dirty = true; };
  // Parts the assembly stepper has not put in yet are hidden; a driver or drag shows them all.
  const showAll = () => {
    for (const part of parts) part.group.visible = true;
    changed();
  };

  // ---- highlight ----
  // Unchanged highlights change nothing, so that a drag or a step animating frame after frame
  // keeps the cache of the still parts.
  let highlighted = null;
  const highlight = (indices) => {
    const key = indices.join(",");
    if (key === highlighted) return;
    highlighted = key;
    changed();
    const on = new Set(indices);
    parts.forEach((part, p) => {
      part.material.emissive.setHex(on.has(p) ? 0x3355ff : 0x000000);
      part.material.emissiveIntensity = on.has(p) ? 0.6 : 0;
    });
  };
  const partIndex = (id) => data.parts.findIndex((p) => p.id === id);

  // ---- clashes and gaps ----
  // Parts in a clash at rest: red, with a dot where they meet.
  const clashing = new Set();
  const dotSize = Math.max(data.reach_mm, 1) / 150;
  // A red dot at a contact point, drawn over everything.
  const contactDot = (point) => {
    const dot = new THREE.Mesh(new THREE.SphereGeometry(1, 12, 8),
      new THREE.MeshBasicMaterial({ color: 0xdd1111, depthTest: false }));
    dot.position.set(point[0], point[1], point[2]);
    dot.scale.setScalar(dotSize);
    dot.renderOrder = 1;
    return dot;
  };
  for (const c of data.clashes) {
    c.parts.forEach((p) => clashing.add(p));
    scene.add(contactDot(c.point));
  }
  for (const p of clashing) {
    parts[p].color.setRGB(0.85, 0.05, 0.05);
    parts[p].material.color.copy(parts[p].color);
  }
  // Enclosed gaps: translucent blue volumes, drawn inside the parts.
  data.gaps.forEach((g) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position",
      new THREE.BufferAttribute(decode(g.triangles, Float32Array), 3));
    geometry.computeVertexNormals();
    scene.add(new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({
      color: 0x1a59f2, transparent: true, opacity: 0.45, side: THREE.DoubleSide,
      depthWrite: false, clippingPlanes: clipping })));
  });

  // A driver's run at s: the parts on its paths, and the clashes the swept check found on the
  // way (contacts reached by s) red with a dot where they meet. Returns those clashes.
  const runDots = new THREE.Group();
  scene.add(runDots);
  // Back to the colours at rest, without the run's dots (when a run marked any).
  let runMarked = false;
  const clearRun = () => {
    if (!runMarked) return;
    while (runDots.children.length) runDots.remove(runDots.children[0]);
    for (const part of parts) part.material.color.copy(part.color);
    runMarked = false;
    changed();
  };
  const runDriver = (i, s) => {
    const d = data.drivers[i];
    state.driver = i;
    leaveSteps();
    show(d.paths, s);
    const met = (d.clashes || []).filter((c) => c.at <= s);
    clearRun();
    const red = new Set();
    for (const c of met) {
      c.parts.forEach((p) => red.add(p));
      runDots.add(contactDot(c.point));
    }
    for (const p of red) parts[p].material.color.setRGB(0.85, 0.05, 0.05);
    runMarked = met.length > 0;
    if (runMarked) changed();
    return met.map((c) => ({ parts: c.parts.map((p) => data.parts[p].id), at: c.at }));
  };

  // ---- panel ----
  $("title").textContent = data.name || "assembly";
  const unit = (driver) => (driver.together ? "s" : driver.rotation ? "rev" : data.length_unit);
  // A run's parameter in words: degrees of a turn, length units of a slide, time of all
  // drivers together.
  const runWords = (d, s) => (d.rotation ? (360 * s).toFixed(1) + " deg" :
    s.toFixed(2) + " " + unit(d));
  data.drivers.forEach((d, i) => {
    const row = document.createElement("div");
    row.appendChild(text("span", d.id + " "));
    if (!d.possible) {
      row.appendChild(text("span", "still: " + d.reason, "warning"));
      $("drivers").appendChild(row);
      return;
    }
    const slider = document.createElement("input");
    Object.assign(slider, { type: "range", min: 0, max: 1000, value: 0, id: "driver-" + i });
    const label = text("span", "");
    const play = text("button", "play");
    // The run's parameter counts revolutions, or the file's length units, as its paths do.
    const set = () => {
      const s = (slider.value / 1000) * d.amount;
      const met = runDriver(i, s);
      label.textContent = " " + runWords(d, s) +
        (met.length ? ": " + met[0].parts.join(" meets ") : "");
      label.className = met.length ? "error" : "";
    };
    slider.addEventListener("input", set);
    let timer = null;
    play.addEventListener("click", () => {
      if (timer) { clearInterval(timer); timer = null; play.textContent = "play"; return; }
      play.textContent = "stop";
      timer = setInterval(() => { slider.value = (Number(slider.value) + 5) % 1001; set(); }, 30);
    });
    row.append(slider, play, label);
    $("drivers").appendChild(row);
  });
  if (!data.drivers.length) $("drivers").textContent = "no driver";
  data.drivers.forEach((d) => {
    if (d.clashes && d.clashes.length) {
      $("drivers").appendChild(text("div", d.id + " runs into a clash: " + d.clashes.map((c) =>
        data.parts[c.parts[0]].id + " meets " + data.parts[c.parts[1]].id + " at " +
        runWords(d, c.at)).join("; "), "error"));
    }
  });

  const mobility = data.mobility;
  $("mobility").appendChild(text("div", "mobility " + mobility.dof + ", " + mobility.redundant +
    " redundant constraints"));
  // Free motions folded under one line: a real file may have dozens.
  const free = document.createElement("details");
  free.appendChild(text("summary", mobility.free.length + " free motion" +
    (mobility.free.length === 1 ? "" : "s") + " (nothing drives or holds them)",
    mobility.free.length ? "warning" : ""));
  for (const f of mobility.free) {
    const row = text("div", data.parts[f.part].id + " " + f.freedom, "row warning");
    row.addEventListener("click", () => highlight([f.part].concat(f.parts)));
    free.appendChild(row);
  }
  if (mobility.free.length) $("mobility").appendChild(free);
  data.clashes.forEach((c) => {
    const row = text("div", data.parts[c.parts[0]].id + " and " + data.parts[c.parts[1]].id +
      " clash, depth " + (typeof c.depth === "number" ? c.depth.toFixed(3) + " mm" : c.depth),
      "row error");
    row.addEventListener("mouseenter", () => highlight(c.parts));
    row.addEventListener("mouseleave", () => highlight([]));
    $("clashes").appendChild(row);
  });
  if (!data.clashes.length) $("clashes").textContent = "no clash at rest";
  data.gaps.forEach((g, i) => {
    $("gaps").appendChild(text("div", "gap " + (i + 1) + ": " + g.volume.toFixed(1) + " +/- " +
      g.error.toFixed(1) + " mm^3"));
  });

  data.expectations.forEach((e) => {
    $("expectations").appendChild(text("div", (e.passed ? "passed " : "FAILED ") + e.what +
      (e.passed ? "" : ": " + e.detail), e.passed ? "passed" : "failed"));
  });
  if (!data.expectations.length) $("expectations").textContent = "none in the file";

  // The parts tree: the CAD product structure ("group", a path with "/"), then the parts.
  const tree = { children: new Map(), parts: [] };
  data.parts.forEach((p, i) => {
    let node = tree;
    for (const name of (p.group || "").split("/").filter((n) => n)) {
      if (!node.children.has(name)) node.children.set(name, { children: new Map(), parts: [] });
      node = node.children.get(name);
    }
    node.parts.push(i);
  });
  const partsOf = (node) => node.parts.concat(...[...node.children.values()].map(partsOf));
  const drawTree = (node, into) => {
    for (const [name, child] of node.children) {
      const d = document.createElement("details");
      const summary = text("summary", name);
      summary.addEventListener("mouseenter", () => highlight(partsOf(child)));
      summary.addEventListener("mouseleave", () => highlight([]));
      d.appendChild(summary);
      drawTree(child, d);
      into.appendChild(d);
    }
    for (const i of node.parts) {
      const row = text("div", data.parts[i].id + (data.parts[i].ground ? " (ground)" : ""), "row");
      row.addEventListener("mouseenter", () => highlight([i]));
      row.addEventListener("mouseleave", () => highlight(selected === null ? [] : [selected]));
      row.addEventListener("click", () => select(i));
      into.appendChild(row);
    }
  };
  drawTree(tree, $("parts"));

  data.subassemblies.forEach((s, i) => {
    const row = text("div", "S" + (i + 1) + (s.ground ? " (ground)" : "") + ": " +
      s.parts.map((p) => data.parts[p].id).join(" "), "row");
    row.addEventListener("mouseenter", () => highlight(s.parts));
    row.addEventListener("mouseleave", () => highlight([]));
    $("subassemblies").appendChild(row);
  });
  // The pair graph between subassemblies: a node per subassembly on a circle, an edge per pair
  // joining two of them (pairs inside one are the fixed ones that made it).
  const svgNs = "http://www.w3.org/2000/svg";
  const svg = document.createElementNS(svgNs, "svg");
  svg.setAttribute("width", 340);
  svg.setAttribute("height", 240);
  const groupOf = data.parts.map((p) => p.subassembly);
  const n = data.subassemblies.length;
  const nodeAt = (i) => [170 + 95 * Math.cos((2 * Math.PI * i) / n - Math.PI / 2),
                         120 + 95 * Math.sin((2 * Math.PI * i) / n - Math.PI / 2)];
  const seen = new Map();  // parallel edges between two nodes bend apart
  data.pairs.forEach((p, i) => {
    const a = groupOf[p.parts[0]], b = groupOf[p.parts[1]];
    if (a === b) return;
    const key = Math.min(a, b) + "-" + Math.max(a, b);
    const k = seen.get(key) || 0;
    seen.set(key, k + 1);
    const [x1, y1] = nodeAt(a), [x2, y2] = nodeAt(b);
    const bend = (k % 2 ? -1 : 1) * Math.ceil(k / 2) * 14;
    const [mx, my] = [(x1 + x2) / 2, (y1 + y2) / 2];
    const len = Math.hypot(x2 - x1, y2 - y1) || 1;
    const [cx, cy] = [mx - ((y2 - y1) / len) * bend, my + ((x2 - x1) / len) * bend];
    const edge = document.createElementNS(svgNs, "path");
    edge.setAttribute("d", "M" + x1 + "," + y1 + " Q" + cx + "," + cy + " " + x2 + "," + y2);
    const coupling = p.dof === undefined;
    edge.setAttribute("stroke", coupling ? "#c0392b" : "#555");
    edge.setAttribute("stroke-dasharray", coupling ? "4 3" : "");
    edge.setAttribute("fill", "none");
    edge.setAttribute("stroke-width", 2);
    edge.setAttribute("class", "edge");
    const title = document.createElementNS(svgNs, "title");
    title.textContent = "P" + (i + 1) + " " + p.type + (p.ratio ? " " + p.ratio : "") + ": " +
      p.a + " + " + p.b;
    edge.appendChild(title);
    edge.addEventListener("mouseenter", () => highlight(p.parts));
    edge.addEventListener("mouseleave", () => highlight([]));
    svg.appendChild(edge);
  });
  data.subassemblies.forEach((sub, i) => {
    const [x, y] = nodeAt(i);
    const c = data.parts[sub.parts[0]].color;
    const node = document.createElementNS(svgNs, "circle");
    Object.entries({ cx: x, cy: y, r: 11, stroke: "#333",
      fill: "rgb(" + c.map((v) => Math.round(255 * v)).join(",") + ")" })
      .forEach(([k, v]) => node.setAttribute(k, v));
    node.setAttribute("class", "node");
    node.addEventListener("mouseenter", () => highlight(sub.parts));
    node.addEventListener("mouseleave", () => highlight([]));
    const label = document.createElementNS(svgNs, "text");
    label.setAttribute("x", x + 13);
    label.setAttribute("y", y + 4);
    label.setAttribute("font-size", 11);
    label.textContent = "S" + (i + 1) + (sub.ground ? " ground" : "");
    svg.append(node, label);
  });
  $("graph").appendChild(svg);
  $("graph").appendChild(text("div", "solid: joints; dashed: couplings (gears, worms, racks)", "info"));

  data.pairs.forEach((p, i) => {
    let words = "P" + (i + 1) + " " + p.type + ": " + p.a + " + " + p.b;
    if (p.ratio) words += ", ratio " + p.ratio;
    if (p.fastening) words += ", " + p.fastening;
    if (p.source !== "recognised" && p.source !== p.fastening) words += " (" + p.source + ")";
    const row = text("div", words, "row");
    row.addEventListener("mouseenter", () => highlight(p.parts));
    row.addEventListener("mouseleave", () => highlight(selected === null ? [] : [selected]));
    $("pairs").appendChild(row);
  });
  data.diagnostics.forEach((d) => {
    const row = text("div", d.severity + " " + d.code + ": " + d.message, "row " + d.severity);
    row.addEventListener("click", () => highlight(d.parts.map(partIndex)));
    $("diagnostics").appendChild(row);
  });
  if (!data.diagnostics.length) $("diagnostics").textContent = "none";

  // ---- drag ----
  let selected = null;
  const dragSlider = $("drag"), dragMode = $("drag-mode");
  const dragMotion = () => data.drags[selected][dragMode.value];
  // A red dot where two parts meet at the end of a drag's movable range.
  const stopMarker = contactDot([0, 0, 0]);
  stopMarker.visible = false;
  scene.add(stopMarker);
  // Drags part `selected` to s (revolutions, or mm for a slide), stopped by its movable range;
  // returns the contact it stops at, or null.
  const dragTo = (mode, s) => {
    const motion = data.drags[selected][mode];
    let stop = null;
    if (motion.ahead && s > motion.ahead.at) { s = motion.ahead.at; stop = motion.ahead; }
    if (motion.behind && s < -motion.behind.at) { s = -motion.behind.at; stop = motion.behind; }
    state.driver = null;
    leaveSteps();
    clearRun();
    show(motion.paths, s);
    stopMarker.visible = stop !== null;
    if (stop) {
      stopMarker.position.set(stop.point[0], stop.point[1], stop.point[2]);
      highlight([selected].concat(stop.parts));
    }
    $("drag-value").textContent = (mode === "turn" ? (360 * s).toFixed(1) + " deg" :
      (s / data.mm_per_length).toFixed(2) + " " + data.length_unit) +
      (stop ? ": stopped, " + data.parts[stop.parts[0]].id + " meets " +
        data.parts[stop.parts[1]].id : "");
    return stop;
  };
  // The slider spans a revolution each way for a turn, the assembly's size for a slide.
  const setDrag = () => {
    const mode = dragMode.value;
    const s = (dragSlider.value / 1000) * (mode === "turn" ? 1 : data.reach_mm);
    dragTo(mode, s);
  };
  const select = (p) => {
    selected = p;
    highlight(p === null ? [] : [p]);
    dragMode.innerHTML = "";
    stopMarker.visible = false;
    if (p === null) { $("drag-controls").style.display = "none"; return; }
    const drags = data.drags[p];
    const info = [data.parts[p].id];
    for (const mode of ["turn", "slide"]) {
      const d = drags[mode];
      if (!d) continue;
      if (d.possible) {
        dragMode.appendChild(new Option(mode + " about " + d.axis, mode));
      } else {
        info.push(mode + " about " + d.axis + " blocked: " + d.reason +
          (data.parts[p].ground ? "; a ground part" : "") +
          (d.holding.length ? "; held by " + d.holding.map((i) => "P" + (i + 1)).join(", ") : ""));
      }
    }
    $("drag-info").textContent = info.join(". ");
    $("drag-controls").style.display = dragMode.options.length ? "" : "none";
    if (!dragMode.options.length) {
      const held = [];
      for (const mode of ["turn", "slide"]) {
        for (const i of (drags[mode] && drags[mode].holding) || []) held.push(...data.pairs[i].parts);
      }
      highlight([p].concat(held));
    }
    dragSlider.value = 0;
  };
  dragSlider.addEventListener("input", setDrag);
  dragMode.addEventListener("change", () => { dragSlider.value = 0; setDrag(); });

  const raycaster = new THREE.Raycaster();
  const pick = (event) => {
    const r = renderer.domElement.getBoundingClientRect();
    const at = new THREE.Vector2(((event.clientX - r.left) / r.width) * 2 - 1,
      -((event.clientY - r.top) / r.height) * 2 + 1);
    raycaster.setFromCamera(at, camera);
    const hit = raycaster.intersectObjects(scene.children, true)
      .find((h) => h.object.userData.part !== undefined);
    return hit ? hit.object.userData.part : null;
  };
  // Pressing on a part that can move and dragging the mouse sideways moves it (400 pixels: a
  // revolution, or the assembly's size for a slide), the orbit held meanwhile; a click
  // without moving selects.
  let down = null, grab = null;
  const kPixelsPerRange = 400;
  renderer.domElement.addEventListener("pointerdown", (e) => {
    down = [e.clientX, e.clientY];
    const p = pick(e);
    if (p === null) return;
    const movable = ["turn", "slide"].some((m) => data.drags[p][m] && data.drags[p][m].possible);
    if (!movable) return;
    if (selected !== p) select(p);
    grab = { x: e.clientX, value: Number(dragSlider.value) };
    controls.enabled = false;
  });
  renderer.domElement.addEventListener("pointerup", (e) => {
    if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) select(pick(e));
    down = null;
    grab = null;
    controls.enabled = true;
  });
  renderer.domElement.addEventListener("pointermove", (e) => {
    if (grab && dragMode.options.length) {
      dragSlider.value = grab.value + ((e.clientX - grab.x) / kPixelsPerRange) * 1000;
      setDrag();
    }
    const p = pick(e);
    const hover = $("hover");
    hover.style.display = p === null ? "none" : "block";
    if (p !== null) {
      hover.textContent = data.parts[p].id + (data.parts[p].group ? " (" + data.parts[p].group + ")" : "");
    }
  });

  // ---- assembly sequence ----
  // Step k shows the base and the parts of steps before k in place, step k's part (and what
  // it carries) travelling along its direction into place, u of the way (a blocked step only
  // up to its first contact, the obstacle marked), and hides the parts of later steps. The pins
  // the file leaves out show in place from the end of the step after which they go in (the
  // base's from the start), those that cannot go in and those of parts never placed not at all.
  const plan = data.assembly;
  let step = null, stepTimer = null;
  const stepMarker = contactDot([0, 0, 0]);
  stepMarker.visible = false;
  scene.add(stepMarker);
  const pinMeshes = [];  // { mesh, pin, step }: step -1 for the base's pins
  const addPins = (pins, k) => {
    for (const pin of pins) {
      const a = new THREE.Vector3(...pin.ends[0]), b = new THREE.Vector3(...pin.ends[1]);
      const mesh = new THREE.Mesh(
        new THREE.CylinderGeometry(pin.diameter / 2, pin.diameter / 2, a.distanceTo(b), 24),
        new THREE.MeshStandardMaterial({ color: 0x9aa0a8, metalness: 0.6, roughness: 0.4,
                                         side: THREE.DoubleSide, clippingPlanes: clipping }));
      mesh.position.copy(a).add(b).multiplyScalar(0.5);
      mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), b.clone().sub(a).normalize());
      mesh.visible = false;
      scene.add(mesh);
      pinMeshes.push({ mesh, pin, step: k });
    }
  };
  if (plan) {
    addPins(plan.base_pins, -1);
    plan.steps.forEach((st, k) => { if (st.placed) addPins(st.pins, k); });
  }
  // A step that puts a sub-assembly together apart (and an attempt to) is with the steps of
  // that sub-assembly only.
  const sameRoom = (j, k) => plan.steps[j].apart_for === plan.steps[k].apart_for;
  // A step's own pins show once its part is in: at its end, and only if nothing stopped it.
  const showPins = (k, u) => {
    for (const m of pinMeshes) {
      m.mesh.visible = k !== null && m.pin.clear &&
        (m.step < 0 ? plan.steps[k].apart_for === null : sameRoom(m.step, k)) &&
        (m.step < k || (m.step === k && u >= 1 && plan.steps[k].clear));
    }
  };
  const stepClear = (st) => st.clear && st.pins.every((pin) => pin.clear);
  // An obstacle is a part or a pin the file leaves out (its holes).
  const obstacleWords = (o) =>
    o.pin ? "the pin through " + o.pin.join(", ") : data.parts[o.part].id;
  // Why the first obstacle stops it: an axial fit across the travel, a clash where it stands,
  // or a contact on the way.
  const blockedWords = (blocked_by) => {
    const first = blocked_by[0];
    if (!first) return "blocked by ?";
    if (first.held_by) return "held across its travel by " + first.held_by;
    if (first.clash_at_rest) {
      return "blocked by " + obstacleWords(first) + " where it is (they clash there)";
    }
    return "blocked by " + obstacleWords(first) + " after " +
      (first.travel / data.mm_per_length).toFixed(2) + " " + data.length_unit;
  };
  const stepWords = (st) => {
    const moving = (st.apart_for !== null ?
                    "apart, into the sub-assembly of step " + (st.apart_for + 1) + ": " :
                    st.subassembly ? "sub-assembly " : "") +
      [st.part].concat(st.carried).map((p) => data.parts[p].id).join(" + ");
    const d = st.direction.map((v) => +v.toFixed(3)).join(", ");
    let words = moving + " along (" + d + "), " +
      (st.travel / data.mm_per_length).toFixed(2) + " " + data.length_unit + ": " +
      (st.clear ? "clear" : blockedWords(st.blocked_by));
    for (const pin of st.pins) {
      words += (st.placed ? "; then the pin through " : "; its pin through ") +
        pin.holes.join(", ") + ": " + (pin.clear ? "clear" : blockedWords(pin.blocked_by));
    }
    return words + (st.placed ? "" : " (cannot be placed)");
  };
  // The obstacle of a blocked step is drawn see-through in red, so that the part it stops
  // and the contact point show.
  let obstacleShown = null;  // the obstacle drawn see-through
  const seeThrough = (obstacle) => {
    let differs = false;
    for (const p of new Set([obstacleShown, obstacle])) {
      if (p === null) continue;
      const material = parts[p].material, on = p === obstacle;
      // Drawn again only when something differs: a step animating keeps the cache.
      differs = differs || material.transparent !== on ||
        material.emissive.getHex() !== (on ? 0xaa0000 : 0);
      material.transparent = on;
      material.opacity = on ? 0.45 : 1;
      material.depthWrite = !on;
      material.emissive.setHex(on ? 0xaa0000 : 0x000000);
      material.emissiveIntensity = on ? 0.5 : 0;
    }
    obstacleShown = obstacle;
    if (differs) changed();
  };
  // A pin that stops a step (its holes; null for none) is drawn in red.
  const markPin = (holes) => {
    const key = holes ? holes.join(",") : null;
    for (const m of pinMeshes) {
      const glow = m.pin.holes.join(",") === key ? 0xaa0000 : 0;
      if (m.mesh.material.emissive.getHex() === glow) continue;
      m.mesh.material.emissive.setHex(glow);
      m.mesh.material.emissiveIntensity = glow ? 0.5 : 0;
      changed();
    }
  };
  const stepTo = (k, u) => {
    clearRun();
    const st = plan.steps[k];
    step = k;
    // Not in yet: the parts of later steps, but for those that cannot leave a sub-assembly
    // once it is in; put together apart: all but the sub-assembly's parts, less those of its
    // later steps apart (of all its steps apart, for an attempt: its base and what cannot
    // leave it).
    const later = new Set();
    const partsOf = (other) => [other.part].concat(other.carried);
    const room = st.apart_for;
    if (room === null) {
      plan.steps.forEach((other, j) => {
        const stays = !other.placed && other.apart_for !== null && other.apart_for <= k;
        if (j > k && !stays) partsOf(other).forEach((p) => later.add(p));
      });
    } else {
      const together = new Set(partsOf(plan.steps[room]));
      plan.steps.forEach((other, j) => {
        if (other.apart_for === room && other.placed && (j > k || !st.placed)) {
          partsOf(other).forEach((p) => together.delete(p));
        }
      });
      parts.forEach((part, p) => { if (!together.has(p)) later.add(p); });
    }
    parts.forEach((part, p) => { part.group.visible = !later.has(p); });
    showPins(k, u);
    changed();
    const first = st.clear ? null : st.blocked_by[0] || null;
    const end = first ? first.travel : st.travel;
    const screw = [{ point: [0, 0, 0], axis: st.direction, turns: 0, travel: 1 }];
    const paths = {};
    [st.part].concat(st.carried).forEach((p) => { paths[p] = screw; });
    state.driver = null;
    show(paths, u * end - st.travel);
    const reached = first !== null && u >= 1;
    stepMarker.visible = reached;
    if (reached) {
      stepMarker.position.set(first.point[0], first.point[1], first.point[2]);
    }
    highlight([st.part]);
    seeThrough(reached && !first.pin ? first.part : null);
    markPin(reached && first.pin ? first.pin : null);
    document.querySelectorAll("#assembly-steps .row").forEach((row, j) => {
      row.classList.toggle("on", j === k);
    });
    return { part: data.parts[st.part].id, clear: st.clear, placed: st.placed,
             pins: pinMeshes.filter((m) => m.mesh.visible).length,
             red_pins: pinMeshes.filter((m) => m.mesh.visible &&
                                             m.mesh.material.emissive.getHex() !== 0).length,
             obstacle: reached ? obstacleWords(first) : null,
             at: reached ? first.travel / data.mm_per_length : null,
             hidden: [...later].map((p) => data.parts[p].id) };
  };
  const stopPlaying = () => {
    if (stepTimer) clearInterval(stepTimer);
    stepTimer = null;
    $("step-play").textContent = "play";
  };
  // Animates step k from outside to its end over 40 frames, then the next step.
  const playFrom = (k) => {
    stopPlaying();
    $("step-play").textContent = "stop";
    let u = 0;
    stepTimer = setInterval(() => {
      u = Math.min(u + 0.025, 1);
      stepTo(k, u);
      if (u < 1) return;
      if (k + 1 < plan.steps.length && stepClear(plan.steps[k])) { k += 1; u = 0; return; }
      stopPlaying();
    }, 30);
  };
  function leaveSteps() {
    if (step === null) return;
    stopPlaying();
    step = null;
    stepMarker.visible = false;
    showPins(null, 0);
    seeThrough(null);
    markPin(null);
    showAll();
  }
  if (!plan) {
    $("assembly-summary").textContent = "not planned (mechanist view --plan plans it)";
  } else {
    $("assembly-summary").textContent = (plan.assemblable ? "assemblable" : "not assemblable") +
      ", " + plan.steps.length + " insertion" + (plan.steps.length === 1 ? "" : "s") +
      (plan.from_steps ? " (the file's steps)" : " (found by disassembly)") + "; in place first: " +
      (plan.base.map((p) => data.parts[p].id).join(" ") || "nothing");
    $("assembly-summary").className = plan.assemblable ? "passed" : "failed";
    $("assembly-controls").style.display = plan.steps.length ? "" : "none";
    plan.steps.forEach((st, k) => {
      const row = text("div", (k + 1) + ". " + stepWords(st),
                       "row" + (stepClear(st) ? "" : " error"));
      row.addEventListener("click", () => { stopPlaying(); stepTo(k, 1); });
      $("assembly-steps").appendChild(row);
    });
    $("step-next").addEventListener("click", () => {
      stopPlaying();
      playFrom(step === null ? 0 : Math.min(step + 1, plan.steps.length - 1));
    });
    $("step-back").addEventListener("click", () => {
      stopPlaying();
      stepTo(step === null || step === 0 ? 0 : step - 1, 1);
    });
    $("step-play").addEventListener("click", () => {
      if (stepTimer) { stopPlaying(); return; }
      playFrom(step === null ? 0 : step);
    });
    $("step-done").addEventListener("click", () => { leaveSteps(); show({}, 0); highlight([]); });
  }

  // ---- view controls ----
  const bounds = () => {
    const box = new THREE.Box3();
    for (const part of parts) box.expandByObject(part.group);
    return box;
  };
  const fit = () => {
    const box = bounds();
    const center = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), 1);
    camera.position.copy(center).add(new THREE.Vector3(1, -1.4, 0.9).multiplyScalar(size));
    camera.near = size / 100;
    camera.far = size * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
  };
  $("fit").addEventListener("click", fit);
  $("show-axes").addEventListener("change", (e) => {
    for (const part of parts) part.axes.visible = e.target.checked || part.sketch;
    changed();
  });
  const setSection = () => {
    clipping.length = 0;
    if ($("section").checked) {
      const box = bounds();
      const x = box.min.x + ($("section-at").value / 1000) * (box.max.x - box.min.x);
      section.constant = x;
      clipping.push(section);
    }
    for (const part of parts) part.material.needsUpdate = true;
    for (const m of pinMeshes) m.mesh.material.needsUpdate = true;
    changed();
  };
  $("section").addEventListener("change", setSection);
  $("section-at").addEventListener("input", setSection);

  const resize = () => {
    const w = view.clientWidth, h = view.clientHeight;
    renderer.setSize(w, h);
    setCacheSize(w * renderer.getPixelRatio(), h * renderer.getPixelRatio());
    changed();
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
  };
  // The view's own size, not the window's: its layout may settle after this script runs (a
  // busy machine), and a canvas sized 0 then would stay blank until the window was resized.
  new ResizeObserver(resize).observe(view);
  resize();
  fit();
  // Drawn when something changed, not every frame: a still page costs nothing.
  const frame = () => {
    if (dirty) draw();
    dirty = false;
    requestAnimationFrame(frame);
  };
  frame();

  // ---- state for scripts and tests ----
  window.mechanist = {
    data,
    /** Milliseconds from the start of navigation to the first frame drawn. */
    loadedMs: performance.now(),
    /** Runs driver `index` to `s` (revolutions, or the file's length units; with several
     *  drivers, the last index runs them all together, `s` in time units): the clashes of
     *  its run reached by then, {parts: [two ids], at}. */
    setDriver(index, s) {
      const d = data.drivers[index];
      const slider = $("driver-" + index);
      if (slider) slider.value = Math.round((1000 * s) / d.amount);
      const met = runDriver(index, s);
      draw();
      return met;
    },
    /** Drags part `id` by `s` revolutions ("turn") or length units ("slide"): true, or
     *  {stop: [the two parts that meet], at} when its movable range ends first; false when
     *  the part cannot move so (see dragInfo). */
    drag(id, s, mode = "turn") {
      select(partIndex(id));
      const d = data.drags[selected][mode];
      if (!d || !d.possible) return false;
      dragMode.value = mode;
      const path_s = s * (mode === "turn" ? 1 : data.mm_per_length);
      dragSlider.value = Math.round((1000 * path_s) / (mode === "turn" ? 1 : data.reach_mm));
      const stop = dragTo(mode, path_s);
      draw();
      return stop ? { stop: stop.parts.map((i) => data.parts[i].id), at: stop.at } : true;
    },
    /** The world pose of part `id` now, column-major. */
    pose(id) { return parts[partIndex(id)].group.matrix.toArray(); },
    /** Degrees part `id` has turned about the world axis `axis` since the file pose. */
    turned(id, axis) {
      const part = parts[partIndex(id)];
      const R = new THREE.Matrix4().multiplyMatrices(part.group.matrix,
        new THREE.Matrix4().getInverse(part.base));
      const q = new THREE.Quaternion().setFromRotationMatrix(R);
      const a = new THREE.Vector3(axis[0], axis[1], axis[2]).normalize();
      return (2 * Math.atan2(new THREE.Vector3(q.x, q.y, q.z).dot(a), q.w) * 180) / Math.PI;
    },
    /** Where a point of part `id`'s world box appears in the page, CSS pixels: its centre, or
     *  `at` (fractions of the box along x, y, z). */
    screenPoint(id, at = [0.5, 0.5, 0.5]) {
      const box = new THREE.Box3().setFromObject(parts[partIndex(id)].group);
      const c = new THREE.Vector3(at[0], at[1], at[2]).multiply(box.getSize(new THREE.Vector3()))
        .add(box.min).project(camera);
      const r = renderer.domElement.getBoundingClientRect();
      return [r.left + ((c.x + 1) / 2) * r.width, r.top + ((1 - c.y) / 2) * r.height];
    },
    /** Shows assembly step k (0-based) u of the way in (default: to its end): the moving part,
     *  whether it is clear, the number of pins shown in place, the obstacle it meets at the end
     *  of a blocked step and after how many length units, and the parts of later steps, hidden. */
    assemblyStep(k, u = 1) {
      const result = stepTo(k, u);
      draw();
      return result;
    },
    /** Draws the still parts from a cache while parts move (on by itself above 200,000
     *  triangles, where multisampling is off too): whether the cache is used; for tests. */
    setCache(on) {
      cache.on = on;
      cache.drawn = "";
      draw();
      return cache.on && canCache;
    },
    /** How many frames the page has drawn (it draws only when something changed). */
    framesDrawn() { return framesDrawn; },
    /** The drag info line shown for the selected part. */
    dragInfo() { return $("drag-info").textContent; },
    select(id) { select(id === null ? null : partIndex(id)); },
  };
})();
</script>
</body>
</html>
)html";

}  // namespace mechanist
