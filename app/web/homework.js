// Homework 8 in the browser: the student's simulateEuler and simulateVerlet, written in JavaScript
// in the page's panel, run beside springlab's methods and checked by the same checker as a
// rope.cpp (the app calls in through web/js_rope.cpp; the checker is the core's).
//
// The student's code runs on the page's own thread, as the app's steps must come back within the
// frame. It is guarded instead: parsed with acorn (Debian's node-acorn, served beside this file),
// every loop's body is given a call of tick(), which throws once the call's time is up (and again
// at every later loop, so a try/catch in the student's loop cannot keep it going); recursion ends
// in the engine's own RangeError. The code runs in strict mode, in a function of its own: it
// sees Vector2D and nothing of the page's that it could break by assigning to it.
//
// The rope as the code sees it, as the exercise's C++ has it: rope.masses[i] with position,
// last_position, velocity, forces (Vector2D), start_position, mass (kg) and pinned;
// rope.springs[j] with m1, m2 (masses), k (N/m) and rest_length (m). The constructor is
// springlab's (homework::exercise_rope): the exercise here is the two steps.
//
// Sections: vectors; compiling; ropes and steps (the app's calls); the panel.
(function (root) {
  "use strict";

  // --- Vectors ------------------------------------------------------------------------------
  // The exercise's CGL::Vector2D; JavaScript has no operators to overload, so a.plus(b) for a + b.
  class Vector2D {
    constructor(x = 0, y = 0) { this.x = x; this.y = y; }
    plus(b) { return new Vector2D(this.x + b.x, this.y + b.y); }
    minus(b) { return new Vector2D(this.x - b.x, this.y - b.y); }
    times(s) { return new Vector2D(this.x * s, this.y * s); }
    over(s) { return new Vector2D(this.x / s, this.y / s); }
    neg() { return new Vector2D(-this.x, -this.y); }
    dot(b) { return this.x * b.x + this.y * b.y; }
    norm2() { return this.x * this.x + this.y * this.y; }
    norm() { return Math.sqrt(this.norm2()); }
    unit() { const n = this.norm(); return new Vector2D(this.x / n, this.y / n); }
    toString() { return `(${this.x}, ${this.y})`; }
  }

  // --- Compiling ----------------------------------------------------------------------------

  const kSourceName = "your-rope.js";
  // new Function puts two lines before the body ("function anonymous(...\n) {\n").
  const kHeaderLines = 2;

  class TimeLimit extends Error {}
  let deadline = Infinity, expired = false, ticks = 0;
  function tick() {
    if (expired) throw new TimeLimit("time");
    if ((++ticks & 255) === 0 && performance.now() > deadline) {
      expired = true;
      throw new TimeLimit("time");
    }
  }
  // Runs fn with `ms` of time; returns { value } or { error: "time" | message }.
  function guarded(fn, ms) {
    deadline = performance.now() + ms;
    expired = false;
    try {
      const value = fn();
      return expired ? { error: "time" } : { value };
    } catch (e) {
      if (expired || e instanceof TimeLimit) return { error: "time" };
      return { error: describe(e) };
    } finally {
      deadline = Infinity;
      expired = false;
    }
  }

  // "TypeError: ... (line 12 of your code)": the line from the engine's stack, where it names ours.
  function describe(e) {
    const what = e instanceof Error ? `${e.name}: ${e.message}` : `the value ${String(e)}`;
    const stack = e && typeof e.stack === "string" ? e.stack : "";
    const at = stack.match(new RegExp(kSourceName.replace(".", "\\.") + ":(\\d+):(\\d+)"));
    return at ? `${what} (line ${Number(at[1]) - kHeaderLines} of your code)` : what;
  }

  // Every loop's body begins with a call of the guard. Insertions keep the code's lines.
  function instrument(source) {
    const acorn = root.acorn;
    if (!acorn || !acorn.parse || !acorn.walk) throw new Error("the page's JavaScript parser (acorn.js) did not load");
    let ast;
    try {
      ast = acorn.parse(source, { ecmaVersion: "latest", sourceType: "script", locations: true });
    } catch (e) {
      const where = e.loc ? `line ${e.loc.line}, column ${e.loc.column + 1}` : "";
      throw new Error(`your code does not parse: ${e.message.replace(/ \(\d+:\d+\)$/, "")}${where ? " at " + where : ""}`);
    }
    const edits = [];
    const guard = (node) => {
      const body = node.body;
      if (body.type === "BlockStatement") edits.push([body.start + 1, "__tick();"]);
      else {
        edits.push([body.start, "{__tick();"]);
        edits.push([body.end, "}"]);
      }
    };
    acorn.walk.full(ast, (node) => {
      if (/^(For|ForIn|ForOf|While|DoWhile)Statement$/.test(node.type)) guard(node);
    });
    edits.sort((a, b) => b[0] - a[0]);
    let out = source;
    for (const [at, text] of edits) out = out.slice(0, at) + text + out.slice(at);
    return out;
  }

  let steps = null;  // { euler, verlet }: the functions of the code last compiled without error

  // Compiles the student's code: its two functions, or an Error saying what is wrong.
  function compile(source) {
    const body = '"use strict";' + instrument(String(source)) +
      "\nreturn [typeof simulateEuler === 'function' ? simulateEuler : null," +
      " typeof simulateVerlet === 'function' ? simulateVerlet : null];\n//# sourceURL=" + kSourceName;
    let made;
    try {
      made = new Function("Vector2D", "__tick", body);
    } catch (e) {
      throw new Error(`your code does not compile: ${describe(e)}`);
    }
    // The code's top level runs once here, guarded as the steps are.
    const run = guarded(() => made(Vector2D, tick), 1000);
    if (run.error === "time") throw new Error("your code's top level ran past 1 s (a loop that never ends?)");
    if (run.error) throw new Error(`your code threw when it was loaded: ${run.error}`);
    const [euler, verlet] = run.value;
    const missing = [euler ? "" : "simulateEuler", verlet ? "" : "simulateVerlet"].filter(Boolean);
    if (missing.length)
      throw new Error(`your code defines no function ${missing.join(" and no function ")}: write ` +
                      missing.map((f) => `function ${f}(rope, delta_t, gravity) { ... }`).join(" and "));
    steps = { euler, verlet };
    return steps;
  }

  // --- Ropes and steps (the app's calls, web/js_rope.cpp) -----------------------------------

  const ropes = new Map();
  const kValues = 8;  // a mass's state: x, y, last x, last y, vx, vy, fx, fy

  // masses: [x, y, mass, pinned] each; springs: [m1, m2, k, rest_length] each.
  function build(id, masses, springs) {
    const rope = { masses: [], springs: [] };
    for (let i = 0; i < masses.length; i += 4) {
      const at = () => new Vector2D(masses[i], masses[i + 1]);
      rope.masses.push({ start_position: at(), position: at(), last_position: at(), velocity: new Vector2D(),
                         forces: new Vector2D(), mass: masses[i + 2], pinned: masses[i + 3] !== 0 });
    }
    for (let j = 0; j < springs.length; j += 4)
      rope.springs.push({ m1: rope.masses[springs[j]], m2: rope.masses[springs[j + 1]], k: springs[j + 2],
                          rest_length: springs[j + 3] });
    ropes.set(id, rope);
  }

  function setState(id, state) {
    const rope = ropes.get(id);
    rope.masses.forEach((m, i) => {
      const s = state.subarray(i * kValues, (i + 1) * kValues);
      m.position = new Vector2D(s[0], s[1]);
      m.last_position = new Vector2D(s[2], s[3]);
      m.velocity = new Vector2D(s[4], s[5]);
      m.forces = new Vector2D(s[6], s[7]);
    });
  }

  const kFields = ["position", "last_position", "velocity", "forces"];
  // The masses' state into out at `at`; where a field is not a vector any more, what is wrong as
  // "left <kind> ..." (js_rope.cpp words it in the page's language).
  function read(rope, out, at) {
    for (let i = 0; i < rope.masses.length; ++i) {
      const m = rope.masses[i];
      if (!m || typeof m !== "object") return `left not-a-mass ${i}`;
      for (let f = 0; f < kFields.length; ++f) {
        const v = m[kFields[f]];
        if (!v || typeof v.x !== "number" || typeof v.y !== "number")
          return `left not-a-vector ${i} ${kFields[f]}`;
        out[at + i * kValues + 2 * f] = v.x;
        out[at + i * kValues + 2 * f + 1] = v.y;
      }
    }
    return null;
  }

  // `count` calls of the step (0: simulateEuler, 1: simulateVerlet), with `ms` of time for them
  // all: { states } (the masses' state after each call) or { error, step } (the call, from 0,
  // and what happened: "time" or the exception, or what the call left wrong).
  function simulate(id, which, dt, gx, gy, count, ms) {
    const rope = ropes.get(id);
    if (!steps) return { error: "no code has been compiled", step: 0 };
    const fn = which === 0 ? steps.euler : steps.verlet;
    const n = rope.masses.length;
    const states = new Float64Array(count * n * kValues);
    const gravity = new Vector2D(gx, gy);
    let done = 0, left = null;
    const run = guarded(() => {
      for (; done < count; ++done) {
        fn(rope, dt, new Vector2D(gravity.x, gravity.y));
        if (rope.masses.length !== n) { left = `left count ${n} ${rope.masses.length}`; return; }
        left = read(rope, states, done * n * kValues);
        if (left) return;
      }
    }, ms);
    if (run.error) return { error: run.error, step: done };
    if (left) return { error: left, step: done };
    return { states };
  }

  function drop(id) { ropes.delete(id); }

  const api = { Vector2D, compile, instrument, build, setState, simulate, drop, describe, kValues,
                get compiled() { return steps !== null; } };
  root.springlabHomework = api;

  // --- The panel ----------------------------------------------------------------------------
  if (typeof document === "undefined") return;  // (the tests' Node)

  const kStarter = `// Homework 8: the rope. Write the two steps; then Check and run (Ctrl+Enter).
// rope.masses[i]: position, last_position, velocity, forces (Vector2D), mass, pinned
// rope.springs[j]: m1, m2 (masses), k, rest_length
// Vector2D: a.plus(b), a.minus(b), a.times(s), a.over(s), a.dot(b), a.norm(), a.unit()

function simulateEuler(rope, delta_t, gravity) {
  for (const s of rope.springs) {
    // TODO (Part 2): Use Hooke's law to calculate the force on a node
  }
  for (const m of rope.masses) {
    if (!m.pinned) {
      // TODO (Part 2): Add the force due to gravity, then compute the new velocity and position
      // (explicit Euler, then semi-implicit Euler: the checker tells which one you wrote)

      // TODO (Part 2): Add global damping
    }
    // Reset all forces on each mass
    m.forces = new Vector2D(0, 0);
  }
}

function simulateVerlet(rope, delta_t, gravity) {
  for (const s of rope.springs) {
    // TODO (Part 3): Simulate one timestep of the rope using explicit Verlet
    // (the springs' forces, as in simulateEuler)
  }
  for (const m of rope.masses) {
    if (!m.pinned) {
      const temp_position = m.position;
      // TODO (Part 3.1): Set the new position of the rope mass

      // TODO (Part 4): Add global Verlet damping
    }
    m.forces = new Vector2D(0, 0);
  }
}
`;
  api.starter = kStarter;

  const panel = () => document.getElementById("homework");
  const field = () => document.getElementById("homework-code");
  const report = () => document.getElementById("homework-report");

  function say(text, failed) {
    const r = report();
    r.textContent = text;
    r.classList.toggle("failed", !!failed);
    // (in whatever language the words are: what a test or a style waits out)
    r.classList.toggle("checking", text === words.checking);
  }

  // The panel's words in the app's language (the report comes in it too).
  function translate() {
    let w = {};
    try {
      w = JSON.parse(root.Module.ccall("springlab_homework_words", "string", [], []));
    } catch (e) {
      return;  // (the app not started yet: the page's English stays)
    }
    const set = (id, text, attribute) => {
      const e = document.getElementById(id);
      if (!e || !text) return;
      if (attribute) e.setAttribute(attribute, text);
      else e.textContent = text;
    };
    set("homework", w.title, "aria-label");
    set("homework-title", w.title);
    set("homework-code-label", w.code);
    set("homework-run", w.run);
    set("homework-starter", w.starter);
    set("homework-close", w.close);
    words.checking = w.checking || words.checking;
  }
  const words = { checking: "checking\u2026" };

  function open(code) {
    translate();
    const p = panel();
    if (code !== undefined) field().value = code;
    else if (!field().value) field().value = kStarter;
    p.hidden = false;
    document.body.classList.add("homework-open");
    field().focus();
  }

  function close() {
    panel().hidden = true;
    document.body.classList.remove("homework-open");
    const canvas = document.getElementById("canvas");
    if (canvas) canvas.focus();
  }

  // Compiles the panel's code and hands it to the app, which checks it and runs its lanes; a
  // code that does not compile is said here and in the app, whose last good code runs on.
  function run() {
    const code = field().value;
    try {
      compile(code);
    } catch (e) {
      say(e.message, true);
      root.Module.ccall("springlab_homework_failed", null, ["string"], [e.message]);
      return;
    }
    say(words.checking);
    // (a frame first, so that the page shows it is checking)
    requestAnimationFrame(() => setTimeout(() => {
      const r = JSON.parse(root.Module.ccall("springlab_homework_check", "string", ["string"], [code]));
      say(r.text || "", r.failed !== 0);
    }, 0));
  }

  // The app's own: a link with homework= opens the panel with its code and runs it.
  api.start = (code) => { open(code); run(); };
  api.open = () => open();
  api.run = run;

  document.addEventListener("DOMContentLoaded", () => {
    document.getElementById("homework-run").addEventListener("click", run);
    document.getElementById("homework-starter").addEventListener("click", () => {
      field().value = kStarter;
      field().focus();
    });
    document.getElementById("homework-close").addEventListener("click", close);
  });
  // The panel's keys (index.html hands them over: its keys never reach the app): Ctrl+Enter
  // checks and runs, Escape closes.
  api.key = (e) => {
    if (!panel() || !panel().contains(e.target)) return;
    if (e.key === "Enter" && (e.ctrlKey || e.metaKey)) { e.preventDefault(); run(); }
    if (e.key === "Escape") { e.preventDefault(); close(); }
  };
})(typeof window !== "undefined" ? window : globalThis);
