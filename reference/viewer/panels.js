// topomark's run viewer: the panels beside the drawings (the loop iteration, the checks, the timeline of events).
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("run-data").textContent);
  const $ = (id) => document.getElementById(id);
  const esc = (s) => String(s).replace(/[&<>"]/g, (c) => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"})[c]);
  const dart = (d) => "[" + d[0] + "," + d[1] + "]";
  const V = D.verdict, bad = V.frame;
  const COLOURS = {vertex: "#27ae60", loop: "#2980b9", rejected: "#e67e22", marker: "#8e44ad", violation: "#c0392b", end: "#222"};

  let shownKey = "";
  function showIteration(f, done, closed, h) {
    const its = D.iterations, box = $("tm-iteration"), key = [done, closed, h, D.v0 && D.v0[0] <= f].join();
    if (key === shownKey) return;  // drawn already: stepping within one walk redraws nothing
    shownKey = key;
    $("tm-hypothesis").textContent = "none";
    if (!D.iterations.length && !D.v0) { box.innerHTML = "<p>This trace's family records no algorithm layer: the robot's moves and marker operations only.</p>"; return; }
    if (!D.v0 || D.v0[0] > f) { box.innerHTML = "<p>The lighthouse is being established (Algorithm 3.1 line 1).</p>"; return; }
    const k = closed ? done - 1 : done;
    if (k >= its.length) {
      box.innerHTML = done < D.m ? "<p><b>iteration " + (done + 1) + "</b> of m = " + D.m + " (in progress; its record is not reached)</p>"
        : "<p>After the last iteration (" + done + " of m = " + D.m + ").</p>";
      return;
    }
    const it = its[k];
    let html = "<p><b>iteration " + it.iteration + "</b> of m = " + D.m + (closed ? " (its record: done)" : " (in progress)") +
      ": e = " + dart(it.edge) + ", v_u's signature " + esc(it.signature) + (it.by_marker ? " (the lighthouse: recognised by the marker)" : "") + "</p>";
    html += "<p>join: " + (it.augmentation === "non-loop" ? "non-loop, new vertex v" + it.joined[1][0] : "loop, " + dart(it.joined[0]) + " with " + dart(it.joined[1])) + "</p>";
    if (it.hypotheses.length) {
      html += "<p>H: " + it.hypotheses.length + " hypothes" + (it.hypotheses.length === 1 ? "is" : "es") + "</p><ol start=0 id=tm-hyps>";
      it.hypotheses.forEach((x, i) => {
        const [d, M, PE, outcome, seen, by] = x;
        html += "<li" + (i === h ? " class=current" : "") + ">e' = " + dart(d) + ", M = [" + M.join(",") + "], P<sup>E</sup> = " +
          esc(PE.join(" ")) + " &rarr; <b>" + outcome + "</b>" + (by ? " (rejected by " + by + ")" : "") +
          (seen.length ? ", perceived " + esc(seen.join(" ")) : "") + "</li>";
      });
      html += "</ol>";
    } else html += "<p>H is empty.</p>";
    if (h >= 0) $("tm-hypothesis").textContent = "h" + h + " of iteration " + it.iteration;
    box.innerHTML = html;
  }

  function showChecks(f, record) {
    const list = D.checks[record] || [];
    let html = list.map((c) => "<li class=ok>&#10003; " + esc(c) + "</li>").join("");
    if (f === bad) {
      const v = V.divergence;
      html = "<li class=fail>&#10007; " + esc(v.check) + " at " + esc(v.where) + "</li>";
    }
    $("tm-checks").innerHTML = html || "<li>nothing to check on this record</li>";
    $("tm-verdict").className = V.ok ? "ok" : f === bad ? "fail" : "";
  }

  let canvas, ctx, base, go;
  function drawTimeline() {
    const w = canvas.width = canvas.clientWidth || 800, h = canvas.height;
    ctx.fillStyle = "#f4f4f4"; ctx.fillRect(0, 0, w, h);
    for (const e of D.events) {
      ctx.fillStyle = COLOURS[e[1]] || "#666";
      const x = Math.round(e[0] / Math.max(1, D.frames - 1) * (w - 2));
      ctx.fillRect(x, e[1] === "violation" ? 0 : 8, e[1] === "violation" ? 3 : 1, h - 8);
    }
    base = ctx.getImageData(0, 0, w, h);
  }
  function cursor(f) {
    if (!ctx) return;
    ctx.putImageData(base, 0, 0);
    ctx.fillStyle = "#000";
    ctx.fillRect(Math.round(f / Math.max(1, D.frames - 1) * (canvas.width - 2)) - 1, 0, 3, canvas.height);
  }
  function timeline(goTo) {
    go = goTo;
    canvas = $("tm-timeline"); ctx = canvas.getContext("2d");
    drawTimeline();
    canvas.onclick = (e) => go(Math.round(e.offsetX / canvas.width * (D.frames - 1)));
    const sel = $("tm-events"), shown = D.events.slice(0, 20000);
    sel.innerHTML = shown.map((e) => "<option value=" + e[0] + ">line " + (e[0] + 1) + ": " + esc(e[2]) + "</option>").join("");
    $("tm-event-count").textContent = D.events.length + (D.events.length > shown.length ? " (the first " + shown.length + " listed)" : "");
  }
  window.TM = {data: D, showIteration, showChecks, cursor, timeline};
})();
