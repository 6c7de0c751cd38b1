// topomark's run viewer: steps through the frames written by topomark.reference.viewer.page (one per trace line).
(function () {
  "use strict";
  const TM = window.TM, D = TM.data;
  const SVGNS = "http://www.w3.org/2000/svg";
  const $ = (id) => document.getElementById(id);
  function column(b64) {
    const raw = atob(b64), bytes = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) bytes[i] = raw.charCodeAt(i);
    return new Int32Array(bytes.buffer);
  }
  const kind = column(D.cols.kind), vertex = column(D.cols.vertex), entry = column(D.cols.entry);
  const walk = column(D.cols.walk), hyp = column(D.cols.hyp);
  const N = kind.length, MOVE = D.records.indexOf("move"), ITER = D.records.indexOf("iteration");
  const steps = new Int32Array(N), done = new Int32Array(N);  // traversals and iterations up to each frame
  for (let f = 0, s = 0, k = 0; f < N; f++) {
    if (kind[f] === MOVE) s++;
    if (kind[f] === ITER) k++;
    steps[f] = s; done[f] = k;
  }
  const K = D.kinds.length, split = new Int32Array(N * K);  // the moves of each kind of walk up to each frame
  for (let f = 0; f < N; f++) {
    if (f > 0) split.copyWithin(f * K, (f - 1) * K, f * K);
    if (walk[f] >= 0) split[f * K + walk[f]]++;
  }
  const stepFrame = new Int32Array(steps[N - 1] + 1);  // the frame of each step's move
  for (let f = 0; f < N; f++) if (kind[f] === MOVE) stepFrame[steps[f]] = f;
  const names = D.vertices, pos = D.pos, rot = D.rotation;
  let frame = 0, playing = false, lastTick = 0, carry = 0, mapShown = -1;

  function last(list, f) {  // the last [frame, ...] entry at or before frame f, by binary search
    let lo = 0, hi = list.length - 1, best = null;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (list[mid][0] <= f) { best = list[mid]; lo = mid + 1; } else hi = mid - 1;
    }
    return best;
  }
  function el(tag, attrs, parent) {
    const e = document.createElementNS(SVGNS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (parent) parent.appendChild(e);
    return e;
  }
  function toward(v, w, d) {  // the point d px from v toward w
    const [x, y] = pos[v], [a, b] = pos[w], L = Math.hypot(a - x, b - y) || 1;
    return [x + (a - x) * Math.min(d / L, 0.45), y + (b - y) * Math.min(d / L, 0.45)];
  }
  function line(g, p, q, style) {
    return el("line", Object.assign({x1: p[0], y1: p[1], x2: q[0], y2: q[1]}, style), g);
  }
  function markerText(m) {
    if (m[0] === "v") return "vertex " + names[m[1]] + (m[2] > 1 ? " x" + m[2] : "") + (m[3] >= 0 ? " -> " + names[m[3]] : "");
    return "edge " + names[m[1]] + "-" + names[m[2]] + (m[3] > 1 ? " x" + m[3] : "") + (m[4] >= 0 ? " head " + names[m[4]] : "");
  }
  function drawMarkers(g, list) {
    for (const m of list) {
      if (m[0] === "v") {
        el("circle", {cx: pos[m[1]][0], cy: pos[m[1]][1], r: 17, fill: "none", stroke: "#e67e22", "stroke-width": 4, class: "marker"}, g);
        if (m[3] >= 0) line(g, pos[m[1]], toward(m[1], m[3], 36), {stroke: "#e67e22", "stroke-width": 4, "marker-end": "url(#tm-arrow-o)"});
      } else {
        const [x, y] = pos[m[1]], [a, b] = pos[m[2]], L = Math.hypot(a - x, b - y) || 1;
        const cx = (x + a) / 2, cy = (y + b) / 2, nx = -(b - y) / L * 9, ny = (a - x) / L * 9;
        line(g, [cx - nx, cy - ny], [cx + nx, cy + ny], {stroke: "#c0392b", "stroke-width": 5, class: "marker"});
        if (m[4] >= 0) {
          const t = m[4] === m[2] ? [m[1], m[2]] : [m[2], m[1]];
          line(g, [cx, cy], toward(t[0], t[1], L * 0.68), {stroke: "#c0392b", "stroke-width": 3, "marker-end": "url(#tm-arrow-r)"});
        }
      }
    }
  }
  function drawThread(g, t) {
    if (!t || t[1].length === 0) return;
    const pts = t[1].map((v) => pos[v][0] + 3 + "," + (pos[v][1] + 3)).join(" ");
    el("polyline", {points: pts, fill: "none", stroke: "#8e44ad", "stroke-width": 3, "stroke-dasharray": "2 3"}, g);
    el("rect", {x: pos[t[1][0]][0] - 6, y: pos[t[1][0]][1] - 6, width: 12, height: 12, fill: "#8e44ad"}, g);
  }
  function drawTrail(g, f) {  // the walk of this iteration so far; the hypothesis under test's walk highlighted
    const from = done[f] === 0 ? 0 : D.iterations[done[f] - 1].frame;
    for (let k = Math.max(from + 1, f - 120); k <= f; k++) {  // the last 120 lines of it at most
      if (kind[k] !== MOVE) continue;
      const p = pos[vertex[k - 1]], q = pos[vertex[k]];
      const tested = hyp[f] >= 0 && hyp[k] === hyp[f] && kind[f] === MOVE;
      line(g, p, q, {stroke: tested ? "#d35400" : "#2980b9", "stroke-width": tested ? 5 : 3, "stroke-opacity": 0.55});
    }
  }
  function drawRobot(g, f) {
    const v = vertex[f], w = rot[v][entry[f]];
    line(g, pos[v], toward(v, w, 30), {stroke: "#16a085", "stroke-width": 3, "marker-end": "url(#tm-arrow-g)"});
    el("circle", {cx: pos[v][0], cy: pos[v][1], r: 7, fill: "#16a085", id: "tm-robot"}, g);
  }
  function mapAt(f) {  // S after frame f: its vertices (world vertex, exit offset) and joins
    const places = [], joins = [];
    if (D.v0 && D.v0[0] <= f) places.push([D.v0[1], D.v0[2]]);
    for (let k = 0; k < done[f]; k++) {
      const it = D.iterations[k];
      if (it.place) places[it.place[0]] = [it.place[1], it.place[2]];
      joins.push(it.joined);
    }
    return {places, joins};
  }
  function drawMap(f) {
    const g = $("tm-map-g"), S = mapAt(f), key = done[f] * 2 + (D.v0 && D.v0[0] <= f ? 1 : 0);
    if (key === mapShown) return S;
    mapShown = key;
    g.textContent = "";
    const worldDart = (d) => { const p = S.places[d[0]], w = p[0]; return [w, rot[w][(p[1] + d[1]) % rot[w].length]]; };
    const joined = new Set();
    for (const [a, b] of S.joins) {
      joined.add(a[0] + ":" + a[1]); joined.add(b[0] + ":" + b[1]);
      const [u, v] = worldDart(a);
      line(g, pos[u], pos[v], {stroke: "#222", "stroke-width": 2.5});
    }
    let open = 0;
    S.places.forEach((p, u) => {
      for (let i = 0; p && i < rot[p[0]].length; i++) {
        if (joined.has(u + ":" + i)) continue;
        open++;
        const [w, x] = worldDart([u, i]);
        line(g, pos[w], toward(w, x, 34), {stroke: "#c0392b", "stroke-width": 2, "stroke-dasharray": "4 3", class: "unexplored"});
      }
    });
    S.places.forEach((p, u) => {
      if (!p) return;
      el("circle", {cx: pos[p[0]][0], cy: pos[p[0]][1], r: 11, fill: u === 0 ? "#222" : "#fff", stroke: "#222"}, g);
      el("text", {x: pos[p[0]][0], y: pos[p[0]][1] + 3.5, "font-size": 9, "text-anchor": "middle", fill: u === 0 ? "#fff" : "#222"}, g).textContent = "v" + u;
    });
    $("tm-unexplored").textContent = open;
    return S;
  }
  const render = window.tmRender = function () {
    const f = frame, g = $("tm-overlay");
    g.textContent = "";
    const marks = last(D.markers, f), thread = last(D.thread, f);
    drawTrail(g, f);
    drawMarkers(g, marks ? marks[1] : []);
    drawThread(g, thread);
    drawRobot(g, f);
    const S = drawMap(f);
    $("tm-frame").value = f;
    $("tm-line").textContent = (f + 1) + " of " + N + " (" + D.records[kind[f]] + ")";
    $("tm-cost").textContent = steps[f];
    $("tm-robot-vertex").textContent = names[vertex[f]];
    $("tm-heading").textContent = "exit " + entry[f] + " (toward " + names[rot[vertex[f]][entry[f]]] + ")";
    $("tm-markers").textContent = marks && marks[1].length ? marks[1].map(markerText).join("; ") : "none";
    $("tm-thread").textContent = thread && thread[1].length ? thread[1].map((v) => names[v]).join(" ") + (thread[2] ? " (end held)" : " (end left)") : "none";
    $("tm-map-vertices").textContent = S.places.filter((p) => p).length;
    TM.showIteration(f, done[f], kind[f] === ITER, hyp[f]);
    TM.showChecks(f, D.records[kind[f]]);
    const row = split.subarray(f * K, f * K + K);
    $("tm-split").innerHTML = D.kinds.map((k, i) => "<tr" + (row[i] ? "" : " class=zero") + "><td>" + k + "</td><td id='tm-kind-" + i + "'>" + row[i] + "</td></tr>").join("");
    TM.cursor(f);
  };
  function go(f) { frame = Math.max(0, Math.min(N - 1, f | 0)); render(); return frame; }
  function tick(t) {
    if (!playing) return;
    const rate = +$("tm-speed").value;
    carry += rate * Math.min(0.25, (t - (lastTick || t)) / 1000);
    lastTick = t;
    if (carry >= 1) { const k = Math.floor(carry); carry -= k; go(frame + k); }
    if (frame >= N - 1) { play(false); return; }
    requestAnimationFrame(tick);
  }
  function play(on) {
    playing = on === undefined ? !playing : on;
    $("tm-play").textContent = playing ? "pause" : "play";
    lastTick = 0; carry = 0;
    if (playing) requestAnimationFrame(tick);
  }
  const events = D.events;
  function nextEvent(dir) {
    if (dir > 0) { for (const e of events) if (e[0] > frame) return go(e[0]); return go(N - 1); }
    for (let k = events.length - 1; k >= 0; k--) if (events[k][0] < frame) return go(events[k][0]);
    return go(0);
  }
  window.topomarkView = {go, frames: N, frame: () => frame, frameOfStep: (s) => stepFrame[s], play, nextEvent};
  $("tm-first").onclick = () => go(0);
  $("tm-back").onclick = () => go(frame - 1);
  $("tm-play").onclick = () => play();
  $("tm-fwd").onclick = () => go(frame + 1);
  $("tm-last").onclick = () => go(N - 1);
  $("tm-prev-event").onclick = () => nextEvent(-1);
  $("tm-next-event").onclick = () => nextEvent(1);
  $("tm-frame").onchange = () => go(+$("tm-frame").value);
  $("tm-step").onchange = () => { const s = Math.max(0, Math.min(steps[N - 1], +$("tm-step").value | 0)); go(s === 0 ? 0 : stepFrame[s]); };
  $("tm-events").onchange = () => go(+$("tm-events").value);
  document.addEventListener("keydown", (e) => {
    if (e.target.tagName === "INPUT" || e.target.tagName === "SELECT") return;
    const by = e.shiftKey ? 10 : 1;
    const keys = {ArrowRight: () => go(frame + by), ArrowLeft: () => go(frame - by), PageDown: () => go(frame + 100),
      PageUp: () => go(frame - 100), Home: () => go(0), End: () => go(N - 1), " ": () => play(),
      n: () => nextEvent(1), p: () => nextEvent(-1)};
    if (keys[e.key]) { keys[e.key](); e.preventDefault(); }
  });
  TM.timeline(go);
  go(D.open);
})();
