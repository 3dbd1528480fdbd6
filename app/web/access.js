// springlab in words: a document beside the canvas, kept in step with the app, that a screen
// reader walks and a keyboard operates (the canvas alone is one node to them). It holds the scene
// and its description, the method and scene choices, play, step and reset, the physics' sliders
// with their values and units, each lane's method, time, stability verdict and energy, and the
// lesson's step with back and next; the changes that matter are said in a polite live region
// (a lane that diverges, with when and why; a lane past its stability limit; a lesson's step; the
// app's message), once each, never every frame. Its words come from the app (web/access.cpp), in
// the app's language. Hidden from sight until the keyboard enters it; then shown, over the scene.
//
// With prefers-reduced-motion, a lesson's steps start paused. And a lane's energy can be heard, as
// Desmos's audio trace plays a graph: a tone whose pitch rises an octave for each energy scale of
// the scene that the lane has gained since its start (explicit Euler's climbs, symplectic
// Euler's holds), silent once the lane diverges. Off until asked for (the checkbox: a browser
// plays sound only after such a gesture).
(function () {
  "use strict";
  const $ = (id) => document.getElementById(id);
  const call = (name, ret, types, args) => window.Module.ccall(name, ret, types, args);
  const announced = [];  // what the live region said, in order (for the tests)
  window.springlabAnnounced = announced;
  const reduceMotion = window.matchMedia && window.matchMedia("(prefers-reduced-motion: reduce)").matches;

  function say(text) {
    if (!text) return;
    announced.push(text);
    const live = $("access-live");
    // (a new node each time: screen readers say an added node, not always a changed one)
    const p = document.createElement("p");
    p.textContent = text;
    live.replaceChildren(p);
  }

  // A slider's place (0 to 1000) for a value, and back: logarithmic where the panel's is. A range
  // from 0 that is logarithmic (k_d, drag) goes as (e^(k p) - 1) / (e^k - 1), k = ln 10^4.
  const kSteps = 1000, kLog0 = Math.log(1e4);
  function place(c, v) {
    let p;
    if (!c.log) p = (v - c.lo) / (c.hi - c.lo);
    else if (c.lo > 0) p = Math.log(v / c.lo) / Math.log(c.hi / c.lo);
    else p = Math.log1p((v / c.hi) * (Math.exp(kLog0) - 1)) / kLog0;
    return Math.round(Math.min(1, Math.max(0, p)) * kSteps);
  }
  function value(c, at) {
    const p = at / kSteps;
    if (!c.log) return c.lo + p * (c.hi - c.lo);
    if (c.lo > 0) return c.lo * Math.pow(c.hi / c.lo, p);
    return c.hi * (Math.exp(kLog0 * p) - 1) / (Math.exp(kLog0) - 1);
  }
  const shown = (v) => (Math.abs(v) >= 1e4 || (v !== 0 && Math.abs(v) < 1e-2) ? v.toExponential(2) : String(+v.toPrecision(3)));
  // "k_s (N/m)" -> "7500 N/m"
  const withUnit = (c, v) => { const u = c.label.match(/[(\uff08]([^)\uff09]*)[)\uff09]\s*$/); return shown(v) + (u ? " " + u[1] : ""); };

  let controls = [];  // the app's, as last described
  const touched = {};  // slider id -> when the keyboard last moved it (its value is the user's meanwhile)

  // A slider as WAI-ARIA's slider pattern (a native range input's value would be read as its
  // place, 0 to 1000: Chromium ignores aria-valuetext on one): arrows move it a hundredth of its
  // travel, Page Up and Down a tenth, Home and End to its ends; it says its value with its unit.
  function showSlider(el, c, v) {
    const at = place(c, v);
    el.setAttribute("aria-valuenow", String(+v.toPrecision(6)));
    el.setAttribute("aria-valuemin", String(c.lo));
    el.setAttribute("aria-valuemax", String(c.hi));
    el.setAttribute("aria-valuetext", withUnit(c, v));
    el.textContent = withUnit(c, v);
    el.style.setProperty("--at", `${(100 * at) / kSteps}%`);
    el.dataset.at = String(at);
  }
  function moveSlider(el, c, at) {
    at = Math.min(kSteps, Math.max(0, at));
    const v = value(c, at);
    touched[c.id] = performance.now();
    showSlider(el, c, v);
    el.dataset.at = String(at);
    call("springlab_control", "number", ["string", "number"], [c.id, v]);
  }
  function buildSliders(list) {
    const box = $("access-sliders");
    box.replaceChildren();
    for (const c of list) {
      const label = document.createElement("span");
      label.id = "access-" + c.id + "-label";
      label.className = "label";
      label.textContent = c.label;
      const el = document.createElement("div");
      Object.assign(el, { id: "access-" + c.id, tabIndex: 0, className: "slider" });
      el.setAttribute("role", "slider");
      el.setAttribute("aria-labelledby", label.id);
      const row = document.createElement("div");
      row.append(label, el);
      box.append(row);
    }
  }
  // The keys on a slider (index.html hands the document's keys over).
  function key(e) {
    const el = e.target;
    if (!el || el.getAttribute("role") !== "slider" || !el.id.startsWith("access-")) return;
    const c = controls.find((k) => "access-" + k.id === el.id);
    if (!c) return;
    const at = Number(el.dataset.at || 0);
    const moves = { ArrowRight: 10, ArrowUp: 10, ArrowLeft: -10, ArrowDown: -10, PageUp: 100, PageDown: -100 };
    if (e.key in moves) moveSlider(el, c, at + moves[e.key]);
    else if (e.key === "Home") moveSlider(el, c, 0);
    else if (e.key === "End") moveSlider(el, c, kSteps);
    else return;
    e.preventDefault();
  }

  function fillSelect(select, items, current) {
    const names = items.map((i) => i.name).join("\n");
    if (select.dataset.names !== names) {
      select.replaceChildren(...items.map((i) => new Option(i.label, i.name)));
      select.dataset.names = names;
    }
    if (document.activeElement !== select) select.value = current;
  }

  // A chart's points as a CSV file, saved by the browser.
  function download(index, title) {
    const csv = call("springlab_chart_csv", "string", ["number"], [index]);
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([csv], { type: "text/csv" }));
    a.download = `springlab-${title.replace(/[^\w\u4e00-\u9fff]+/g, "-").replace(/^-|-$/g, "") || "chart"}.csv`;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }

  // --- Sound -------------------------------------------------------------------------------
  const sound = { context: null, tone: null, gain: null, frequency: 0, lane: "" };
  window.springlabSound = sound;
  const kBase = 440, kOctaves = 2;  // Hz at the start; +-2 octaves at most
  function soundSwitch(on) {
    if (on && !sound.context) {
      const Context = window.AudioContext || window.webkitAudioContext;
      if (!Context) return say("this browser plays no sound");
      sound.context = new Context();
      sound.tone = sound.context.createOscillator();
      sound.gain = sound.context.createGain();
      sound.gain.gain.value = 0.06;
      sound.tone.frequency.value = kBase;
      sound.tone.connect(sound.gain).connect(sound.context.destination);
      sound.tone.start();
    } else if (!on && sound.context) {
      sound.context.close();
      Object.assign(sound, { context: null, tone: null, gain: null, frequency: 0, lane: "" });
    }
  }
  function soundFollow(d) {
    const select = $("access-sound-lane");
    fillSelect(select, d.lanes.map((l, i) => ({ name: String(i), label: l.label })), select.value || "0");
    if (!sound.context) return;
    const l = d.lanes[Number(select.value) || 0];
    if (!l) return;
    const rise = l.scale > 0 && l.energy !== null ? (l.energy - l.energy0) / l.scale : 0;
    sound.frequency = l.diverged ? 0 : kBase * Math.pow(2, Math.max(-kOctaves, Math.min(kOctaves, rise)));
    sound.lane = l.label;
    const now = sound.context.currentTime;
    sound.gain.gain.setTargetAtTime(l.diverged ? 0 : 0.06, now, 0.05);
    if (sound.frequency > 0) sound.tone.frequency.setTargetAtTime(sound.frequency, now, 0.05);
  }

  let last = null;  // the last description
  const laneState = {};  // a lane's label -> { diverged, tone }
  let lessonKey = "";

  function update(d) {
    $("access-scene-text").textContent = d.description;
    $("access-scene-label").textContent = d.labels.scene;
    $("access-method-label").textContent = d.labels.method;
    fillSelect($("access-scene"), d.scenes.map((s) => ({ name: s, label: s })), d.scene);
    fillSelect($("access-method"), d.methods, d.method);
    $("access-pause").textContent = d.paused ? d.labels.resume : d.labels.pause;
    $("access-step").textContent = d.labels.step;
    $("access-back").textContent = d.labels.back;
    $("access-next").textContent = d.labels.next;
    $("access-reset").textContent = d.labels.reset;
    if (controls.map((c) => c.id + c.label).join() !== d.controls.map((c) => c.id + c.label).join()) buildSliders(d.controls);
    controls = d.controls;
    for (const c of controls) {
      const el = $("access-" + c.id);
      if (!el || performance.now() - (touched[c.id] || -1e9) < 1500) continue;
      showSlider(el, c, c.value);
    }
    // The lanes, and what changed in them that matters.
    const items = d.lanes.map((l) => {
      const energy = l.energy === null ? "" : `; ${d.labels.energy} ${shown(l.energy)} J`;
      return `${l.label}: t = ${l.t.toFixed(2)} s; ${l.verdict}${energy}`;
    });
    const list = $("access-lanes");
    if (list.children.length !== items.length) list.replaceChildren(...items.map(() => document.createElement("li")));
    items.forEach((text, i) => { if (list.children[i].textContent !== text) list.children[i].textContent = text; });
    for (const l of d.lanes) {
      const was = laneState[l.label] || { diverged: false, tone: "" };
      if (l.diverged && !was.diverged) say(`${l.label}, t = ${l.t.toFixed(3)} s: ${l.verdict}. ${l.why}`);
      else if (!l.diverged && l.tone === "beyond" && was.tone !== "beyond") say(`${l.label}: ${l.verdict}`);
      laneState[l.label] = { diverged: l.diverged, tone: l.tone };
    }
    // The lesson.
    const lesson = $("access-lesson");
    lesson.hidden = !d.lesson;
    if (d.lesson) {
      const key = `${d.lesson.title} ${d.lesson.step}`;
      $("access-lesson-title").textContent = `${d.lesson.title}: ${d.lesson.step} / ${d.lesson.steps}, ${d.lesson.step_title}`;
      $("access-lesson-caption").textContent = d.lesson.caption + (d.lesson.prompt ? " " + d.lesson.prompt : "");
      if (key !== lessonKey) {
        lessonKey = key;
        say(`${d.lesson.title}, ${d.lesson.step} / ${d.lesson.steps}: ${d.lesson.step_title}. ${d.lesson.caption}`);
        if (reduceMotion && !d.paused) call("springlab_control", "number", ["string", "number"], ["pause", 1]);
      }
    } else {
      lessonKey = "";
    }
    if (d.message && (!last || last.message !== d.message)) say(d.message);
    // The charts: a sentence each, and its data to download.
    const charts = $("access-charts");
    if (charts.children.length !== d.charts.length) {
      charts.replaceChildren(...d.charts.map((c, i) => {
        const box = document.createElement("div");
        const p = document.createElement("p");
        const button = document.createElement("button");
        button.addEventListener("click", () => download(i, c.title));
        box.append(p, button);
        return box;
      }));
    }
    d.charts.forEach((c, i) => {
      const [p, button] = charts.children[i].children;
      if (p.textContent !== c.summary) p.textContent = c.summary;
      button.textContent = `${d.labels.csv}: ${c.title}`;
    });
    $("access-sound-label").textContent = d.labels.sound;
    soundFollow(d);
    // A particle held by keyboard.
    $("access-particle-label").textContent = d.labels.particle;
    $("access-particle").max = String(d.particles - 1);
    $("access-grab").textContent = d.held >= 0 ? d.labels.release : d.labels.hold;
    for (const k of ["left", "right", "up", "down"]) {
      $("access-" + k).textContent = d.labels[k];
      $("access-" + k).disabled = d.held < 0;
    }
    last = d;
  }

  function refresh() {
    try {
      update(JSON.parse(call("springlab_describe", "string", [], [])));
    } catch (e) {
      console.warn("springlab: the accessible document could not follow the app: " + e.message);
    }
  }

  const act = (name) => () => { call("springlab_control", "number", ["string", "number"], [name, last && name === "pause" ? (last.paused ? 0 : 1) : 0]); setTimeout(refresh, 100); };

  window.springlabAccess = {
    start() {
      $("access-pause").addEventListener("click", act("pause"));
      $("access-step").addEventListener("click", act("step"));
      $("access-reset").addEventListener("click", act("reset"));
      $("access-back").addEventListener("click", act("back"));
      $("access-next").addEventListener("click", act("next"));
      $("access-method").addEventListener("change", (e) => call("springlab_choose", "number", ["string", "string"], ["method", e.target.value]));
      $("access-grab").addEventListener("click", () => {
        if (last && last.held >= 0) call("springlab_control", "number", ["string", "number"], ["release", 0]);
        else call("springlab_control", "number", ["string", "number"], ["hold", Number($("access-particle").value) || 0]);
        setTimeout(refresh, 100);
      });
      for (const k of ["left", "right", "up", "down"])
        $("access-" + k).addEventListener("click", () => call("springlab_control", "number", ["string", "number"], [k, 0]));
      $("access-sound").addEventListener("change", (e) => soundSwitch(e.target.checked));
      $("access-scene").addEventListener("change", (e) => call("springlab_choose", "number", ["string", "string"], ["scene", e.target.value]));
      refresh();
      setInterval(refresh, 250);
    },
    refresh,
    key,
  };
})();
