// tridem live view: draws the run's triangles with WebGL2, instanced (the geometry is
// uploaded once, each frame uploads only poses and colour fields). The wire format is in
// docs/live-view.md and src/live/frame_encoder.hpp.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const canvas = $("canvas");
  // preserveDrawingBuffer: the tests (and screenshots) read the pixels back.
  const gl = canvas.getContext("webgl2", { antialias: true, preserveDrawingBuffer: true });
  const BACKGROUND = [0.12, 0.12, 0.14];
  const PALETTE = [[0.12, 0.47, 0.71], [1.0, 0.5, 0.05], [0.17, 0.63, 0.17], [0.84, 0.15, 0.16],
    [0.58, 0.4, 0.74], [0.55, 0.34, 0.29], [0.89, 0.47, 0.76], [0.74, 0.74, 0.13],
    [0.09, 0.75, 0.81], [0.45, 0.45, 0.95]];

  const live = {  // what the browser tests read
    connected: false, ended: false, replay: 0, step: -1, time: 0, frames: 0, n: 0,
    paused: false, errors: [], positions: null,
  };
  window.tridemLive = live;

  // --- WebGL: one program, per-instance geometry, pose and colour value ---------------
  const VS = `#version 300 es
  layout(location=0) in vec4 a_v01; layout(location=1) in vec2 a_v2;
  layout(location=2) in float a_x; layout(location=3) in float a_y;
  layout(location=4) in float a_angle; layout(location=5) in float a_value;
  layout(location=6) in float a_motion;
  uniform vec2 u_center; uniform vec2 u_scale;
  out float v_value; flat out float v_motion;
  void main() {
    vec2 l = gl_VertexID == 0 ? a_v01.xy : (gl_VertexID == 1 ? a_v01.zw : a_v2);
    float c = cos(a_angle), s = sin(a_angle);
    vec2 p = vec2(a_x + c * l.x - s * l.y, a_y + s * l.x + c * l.y);
    gl_Position = vec4((p - u_center) * u_scale, 0.0, 1.0);
    v_value = a_value; v_motion = a_motion;
  }`;
  const FS = `#version 300 es
  precision highp float;
  in float v_value; flat in float v_motion;
  uniform int u_categorical; uniform vec2 u_range; uniform vec3 u_palette[10];
  out vec4 color;
  vec3 viridis(float t) {
    const vec3 c0 = vec3(0.2777, 0.0054, 0.3341), c1 = vec3(0.1051, 1.4046, 1.3846);
    const vec3 c2 = vec3(-0.3309, 0.2148, 0.0951), c3 = vec3(-4.6342, -5.7991, -19.3324);
    const vec3 c4 = vec3(6.2283, 14.1799, 56.6906), c5 = vec3(4.7764, -13.7451, -65.3530);
    const vec3 c6 = vec3(-5.4355, 4.6459, 26.3124);
    return c0 + t * (c1 + t * (c2 + t * (c3 + t * (c4 + t * (c5 + t * c6)))));
  }
  void main() {
    if (v_motion > 0.5) { color = vec4(0.55, 0.55, 0.58, 1.0); return; }
    if (u_categorical == 1) { color = vec4(u_palette[int(mod(v_value + 0.5, 10.0))], 1.0); return; }
    float span = u_range.y - u_range.x;
    float t = span > 0.0 ? clamp((v_value - u_range.x) / span, 0.0, 1.0) : 0.5;
    color = vec4(clamp(viridis(t), 0.0, 1.0), 1.0);
  }`;
  function compile(type, source) {
    const s = gl.createShader(type);
    gl.shaderSource(s, source); gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
    return s;
  }
  if (!gl) { $("status").textContent = "no WebGL2 in this browser"; live.errors.push("no webgl2"); return; }
  const prog = gl.createProgram();
  gl.attachShader(prog, compile(gl.VERTEX_SHADER, VS));
  gl.attachShader(prog, compile(gl.FRAGMENT_SHADER, FS));
  gl.linkProgram(prog);
  const U = (name) => gl.getUniformLocation(prog, name);
  const vao = gl.createVertexArray();
  const geometryBuffer = gl.createBuffer(), poseBuffer = gl.createBuffer();
  const valueBuffer = gl.createBuffer(), motionBuffer = gl.createBuffer();

  let geometry = null;  // {n, local, material, body, motion, flags}
  let frame = null;     // {step, time, n, ranges, x, y, angle, fields}
  let view = { cx: 0, cy: 0, scale: 1 };  // world centre, pixels per metre
  let fitted = false, drawPending = false;

  function instanced(loc, buffer, size, stride, offset) {
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.enableVertexAttribArray(loc);
    gl.vertexAttribPointer(loc, size, gl.FLOAT, false, stride, offset);
    gl.vertexAttribDivisor(loc, 1);
  }

  function onGeometry(buf) {
    const h = new Uint32Array(buf, 0, 4);
    const n = h[1];
    const local = new Float32Array(buf, 16, 6 * n);
    const ids = 16 + 24 * n;
    geometry = {
      n, flags: h[2], local,
      material: new Uint32Array(buf, ids, n), body: new Uint32Array(buf, ids + 4 * n, n),
      motion: new Uint32Array(buf, ids + 8 * n, n),
    };
    live.n = n; $("count").textContent = n;
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, geometryBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, local, gl.STATIC_DRAW);
    instanced(0, geometryBuffer, 4, 24, 0);
    instanced(1, geometryBuffer, 2, 24, 16);
    gl.bindBuffer(gl.ARRAY_BUFFER, motionBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, Float32Array.from(geometry.motion), gl.STATIC_DRAW);
    instanced(6, motionBuffer, 1, 4, 0);
    fitted = false;
  }

  function onFrame(buf) {
    const h = new Uint32Array(buf, 0, 4);
    const dv = new DataView(buf);
    const n = h[1], nf = h[2];
    const ranges = new Float32Array(buf, 32, 2 * nf);
    const base = 32 + 8 * nf;
    const at = (k) => new Float32Array(buf, base + 4 * n * k, n);
    frame = { n, step: Number(dv.getBigInt64(24, true)), time: dv.getFloat64(16, true), ranges,
      x: at(0), y: at(1), angle: at(2), fields: [] };
    for (let k = 0; k < nf; ++k) frame.fields.push(at(3 + k));
    frame.raw = new Float32Array(buf, base, 3 * n);
    live.step = frame.step; live.time = frame.time; live.frames += 1;
    live.positions = [frame.x[0], frame.y[0]];
    $("step").textContent = frame.step; $("time").textContent = frame.time.toPrecision(6);
    frameTimes.push(performance.now());
    if (frameTimes.length > 30) frameTimes.shift();
    if (frameTimes.length > 1)
      $("rate").textContent = ((frameTimes.length - 1) * 1000 /
        (frameTimes[frameTimes.length - 1] - frameTimes[0])).toFixed(1);
    // Ask for the next frame now, not after drawing: a busy browser draws only the latest
    // frame it has (the others are dropped here), and the run's frames keep coming.
    if (!live.replay && !live.ended && ws.readyState === 1) ws.send("next");
    if (!geometry || geometry.n !== n) return;
    if (!fitted) fit();
    requestDraw();
  }
  const frameTimes = [];

  function fit() {
    if (!frame) return;
    let lx = Infinity, ly = Infinity, hx = -Infinity, hy = -Infinity;
    for (let i = 0; i < frame.n; ++i) {
      lx = Math.min(lx, frame.x[i]); hx = Math.max(hx, frame.x[i]);
      ly = Math.min(ly, frame.y[i]); hy = Math.max(hy, frame.y[i]);
    }
    const pad = 0.08 * Math.max(hx - lx, hy - ly, 1e-9);
    view.cx = 0.5 * (lx + hx); view.cy = 0.5 * (ly + hy);
    view.scale = Math.min(canvas.width / (hx - lx + 2 * pad), canvas.height / (hy - ly + 2 * pad));
    fitted = true;
  }

  function colorMode() {
    const mode = $("color").value;
    if (mode === "material") return { categorical: true, values: geometry.material };
    if (mode === "body") return { categorical: true, values: geometry.body };
    const k = { speed: 0, force: 1, damage: 2 }[mode];
    if (k >= frame.fields.length) return { categorical: false, values: frame.fields[0], range: [0, 0], k: 0 };
    return { categorical: false, values: frame.fields[k], range: [frame.ranges[2 * k], frame.ranges[2 * k + 1]], k };
  }

  function requestDraw() {
    if (drawPending) return;
    drawPending = true;
    requestAnimationFrame(draw);
  }

  function draw() {
    drawPending = false;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.round(canvas.clientWidth * dpr), hgt = Math.round(canvas.clientHeight * dpr);
    if (canvas.width !== w || canvas.height !== hgt) { canvas.width = w; canvas.height = hgt; if (!fitted) fit(); }
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    if (geometry && frame && geometry.n === frame.n) {
      gl.useProgram(prog);
      gl.bindVertexArray(vao);
      const n = frame.n;
      gl.bindBuffer(gl.ARRAY_BUFFER, poseBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, frame.raw, gl.STREAM_DRAW);
      instanced(2, poseBuffer, 1, 4, 0);
      instanced(3, poseBuffer, 1, 4, 4 * n);
      instanced(4, poseBuffer, 1, 4, 8 * n);
      const c = colorMode();
      gl.bindBuffer(gl.ARRAY_BUFFER, valueBuffer);
      gl.bufferData(gl.ARRAY_BUFFER, c.values instanceof Float32Array ? c.values : Float32Array.from(c.values), gl.STREAM_DRAW);
      instanced(5, valueBuffer, 1, 4, 0);
      gl.uniform2f(U("u_center"), view.cx, view.cy);
      gl.uniform2f(U("u_scale"), 2 * view.scale / canvas.width, 2 * view.scale / canvas.height);
      gl.uniform1i(U("u_categorical"), c.categorical ? 1 : 0);
      gl.uniform2f(U("u_range"), c.range ? c.range[0] : 0, c.range ? c.range[1] : 0);
      gl.uniform3fv(U("u_palette"), PALETTE.flat());
      gl.drawArraysInstanced(gl.TRIANGLES, 0, 3, n);
      drawLegend(c);
    }
  }

  // --- the legend and the plots (2D canvas) -------------------------------------------
  function viridisCss(t) {  // the shader's map, for the legend
    const c = [[0.2777, 0.0054, 0.3341], [0.1051, 1.4046, 1.3846], [-0.3309, 0.2148, 0.0951],
      [-4.6342, -5.7991, -19.3324], [6.2283, 14.1799, 56.6906], [4.7764, -13.7451, -65.353],
      [-5.4355, 4.6459, 26.3124]];
    const rgb = [0, 1, 2].map((j) => {
      let v = c[6][j];
      for (let k = 5; k >= 0; --k) v = c[k][j] + t * v;
      return Math.round(255 * Math.min(1, Math.max(0, v)));
    });
    return `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
  }
  const UNITS = ["m/s", "N/m", ""];
  function drawLegend(c) {
    const lg = $("legend").getContext("2d");
    lg.fillStyle = "#26262e"; lg.fillRect(0, 0, 284, 44);
    lg.font = "11px sans-serif";
    if (c.categorical) {
      for (let k = 0; k < 10; ++k) {
        lg.fillStyle = `rgb(${PALETTE[k].map((v) => Math.round(255 * v)).join(",")})`;
        lg.fillRect(4 + 28 * k, 4, 22, 16);
        lg.fillStyle = "#ddd"; lg.fillText(String(k), 10 + 28 * k, 34);
      }
      return;
    }
    for (let px = 0; px < 276; ++px) { lg.fillStyle = viridisCss(px / 275); lg.fillRect(4 + px, 4, 1, 16); }
    lg.fillStyle = "#ddd";
    lg.fillText(c.range[0].toPrecision(3), 4, 34);
    const hi = c.range[1].toPrecision(3) + " " + UNITS[c.k];
    lg.fillText(hi, 280 - lg.measureText(hi).width, 34);
    lg.fillStyle = "#8c8c94"; lg.fillText("walls grey", 110, 34);
  }

  const history = { t: [], series: {} };
  const ENERGY = [["kinetic", "#4fc3f7"], ["elastic", "#ffb74d"], ["potential", "#81c784"],
    ["dissipated", "#e57373"], ["total", "#ffffff"]];
  const WALLS = [["wall_fx", "#4fc3f7"], ["wall_fy", "#ffb74d"]];
  let first = null;
  function onStats(s) {
    if (first === null || s.step < (history.lastStep ?? -1)) {
      first = s; history.t = []; history.series = {};
    }
    history.lastStep = s.step;
    const total = (s.kinetic ?? 0) + (s.potential ?? 0) + (s.elastic ?? 0) + (s.dissipated ?? 0) - (s.wall_work ?? 0);
    const firstTotal = (first.kinetic ?? 0) + (first.potential ?? 0) + (first.elastic ?? 0) + (first.dissipated ?? 0) - (first.wall_work ?? 0);
    const row = { kinetic: s.kinetic, elastic: s.elastic, potential: s.potential - first.potential,
      dissipated: s.dissipated, total: total - firstTotal, wall_fx: s.wall_fx, wall_fy: s.wall_fy };
    history.t.push(s.time);
    for (const k in row) (history.series[k] = history.series[k] || []).push(row[k] ?? 0);
    if (history.t.length > 2000) { history.t.shift(); for (const k in history.series) history.series[k].shift(); }
    plot($("energy"), ENERGY); plot($("walls"), WALLS);
  }
  function plot(el, lines) {
    const g = el.getContext("2d"), W = el.width, H = el.height;
    g.fillStyle = "#15151a"; g.fillRect(0, 0, W, H);
    const t = history.t;
    if (t.length < 2) return;
    let lo = Infinity, hi = -Infinity;
    for (const [k] of lines) for (const v of history.series[k]) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
    if (hi - lo < 1e-30) { hi += 1; lo -= 1; }
    const t0 = t[0], t1 = t[t.length - 1] > t0 ? t[t.length - 1] : t0 + 1;
    const X = (v) => 4 + (W - 8) * (v - t0) / (t1 - t0), Y = (v) => H - 14 - (H - 24) * (v - lo) / (hi - lo);
    lines.forEach(([k, color], j) => {
      g.strokeStyle = color; g.beginPath();
      history.series[k].forEach((v, i) => (i ? g.lineTo(X(t[i]), Y(v)) : g.moveTo(X(t[i]), Y(v))));
      g.stroke();
      g.fillStyle = color; g.font = "10px sans-serif"; g.fillText(k, 4 + 56 * j, H - 2);
    });
    g.fillStyle = "#aaa"; g.fillText(hi.toPrecision(3), 4, 10); g.fillText(lo.toPrecision(3), 4 + W / 2, 10);
  }

  // --- zoom and pan ----------------------------------------------------------------------
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    const dpr = window.devicePixelRatio || 1;
    const mx = (e.offsetX * dpr - canvas.width / 2) / view.scale + view.cx;
    const my = (canvas.height / 2 - e.offsetY * dpr) / view.scale + view.cy;
    const f = Math.exp(-e.deltaY * 0.0015);
    view.scale *= f;
    view.cx = mx - (mx - view.cx) / f; view.cy = my - (my - view.cy) / f;
    requestDraw();
  }, { passive: false });
  let drag = null;
  canvas.addEventListener("mousedown", (e) => { drag = [e.clientX, e.clientY]; });
  window.addEventListener("mouseup", () => { drag = null; });
  window.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dpr = window.devicePixelRatio || 1;
    view.cx -= (e.clientX - drag[0]) * dpr / view.scale; view.cy += (e.clientY - drag[1]) * dpr / view.scale;
    drag = [e.clientX, e.clientY];
    requestDraw();
  });
  $("fit").onclick = () => { fit(); requestDraw(); };
  $("color").onchange = () => requestDraw();
  window.addEventListener("resize", () => requestDraw());

  // --- the connection ----------------------------------------------------------------------
  const ws = new WebSocket(`ws://${location.host}/ws`);
  ws.binaryType = "arraybuffer";
  live.send = (text) => ws.send(text);
  ws.onopen = () => { live.connected = true; $("status").textContent = "live"; ws.send("next"); };
  ws.onclose = () => {
    live.connected = false;
    $("status").textContent = live.ended ? "run ended" : "disconnected";
  };
  ws.onmessage = (e) => {
    if (typeof e.data === "string") {
      const m = JSON.parse(e.data);
      if (m.state) onState(m.state); else onStats(m);
      return;
    }
    const kind = new Uint32Array(e.data, 0, 1)[0];
    if (kind === 1) onGeometry(e.data); else if (kind === 2) onFrame(e.data);
  };
  function onState(s) {
    live.paused = s.paused; live.ended = s.ended;
    if (s.replay) { live.replay = s.replay; $("live-controls").hidden = true; $("replay-controls").hidden = false; $("slider").max = s.replay - 1; }
    $("status").textContent = s.ended ? "run ended" : (s.replay ? "replay" : (s.paused ? "paused" : "live"));
    if (document.activeElement !== $("fps")) $("fps").value = s.fps;
  }
  $("pause").onclick = () => ws.send("pause");
  $("resume").onclick = () => ws.send("resume");
  $("single").onclick = () => ws.send("step");
  $("fps").onchange = () => ws.send("fps " + Math.max(1, Math.min(120, Math.round(+$("fps").value || 30))));
  // A replay plays by asking for the frames one after another.
  let player = null;
  const seek = (k) => { $("slider").value = k; $("frame-index").textContent = k; ws.send("seek " + k); };
  $("slider").oninput = () => seek(+$("slider").value);
  $("play").onclick = () => {
    clearInterval(player);
    player = setInterval(() => {
      const k = +$("slider").value + 1;
      if (k >= live.replay) { clearInterval(player); return; }
      seek(k);
    }, 1000 / Math.max(1, +$("fps").value || 10));
  };
  $("stop").onclick = () => clearInterval(player);

  // For the tests: the colour drawn at particle i's centroid, and at a corner.
  function pixelAtWorld(x, y) {
    const px = Math.round((x - view.cx) * view.scale + canvas.width / 2);
    const py = Math.round((y - view.cy) * view.scale + canvas.height / 2);
    const out = new Uint8Array(4);
    gl.readPixels(px, py, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, out);
    return Array.from(out);
  }
  live.probe = (i) => (frame ? pixelAtWorld(frame.x[i], frame.y[i]) : null);
  live.isFree = (i) => (geometry ? geometry.motion[i] === 0 : false);
  live.background = () => { const o = new Uint8Array(4); gl.readPixels(1, 1, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, o); return Array.from(o); };
})();
