// The rapidmc report page: property table, counterexample player and timeline.
// Everything it shows comes from the JSON in #report-data (see rapidmc/check/html.py);
// text always goes in through textContent, never as markup.
(function () {
  "use strict";

  const SVG = "http://www.w3.org/2000/svg";   // a namespace name, not something fetched
  const COLUMN = 24;
  const ROW = 24;
  const data = JSON.parse(document.getElementById("report-data").textContent);
  const files = new Map(data.files.map((file) => [file.name, file.lines]));
  // coverage warnings: "file:line" -> message, shaded in the source view
  // (a warning about a stretch of lines shades every line of it)
  const unreached = new Map();
  for (const w of data.unreached || []) {
    for (let line = w.line; line <= Math.max(w.end_line || 0, w.line); line += 1) {
      unreached.set(w.file + ":" + line, w.message);
    }
  }
  const $ = (id) => document.getElementById(id);

  const player = {
    property: null,     // the property whose counterexample is shown
    steps: [],
    position: 0,        // index into steps (the page counts from 1)
    file: null,         // the file in the source view
    views: new Map(),   // file name -> {element, lines}
    marked: [],         // source lines highlighted for the current step
  };

  // --- small helpers -------------------------------------------------------

  function element(tag, className, text) {
    const node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined && text !== null) node.textContent = text;
    return node;
  }

  function svg(tag, attributes, text) {
    const node = document.createElementNS(SVG, tag);
    for (const [name, value] of Object.entries(attributes || {})) node.setAttribute(name, value);
    if (text !== undefined) node.textContent = text;
    return node;
  }

  function baseName(path) {
    return path.split(/[\\/]/).pop();
  }

  function where(file, line) {
    if (!file) return "";
    return line ? baseName(file) + ":" + line : baseName(file);
  }

  function plural(count, word) {
    return count + " " + word + (count === 1 ? "" : "s");
  }

  function seconds(value) {
    return value < 10 ? value.toFixed(2) + " s" : value.toFixed(1) + " s";
  }

  // --- header and property table -------------------------------------------

  function showSummary() {
    const counts = {HOLDS: 0, VIOLATED: 0, UNKNOWN: 0};
    for (const property of data.properties) counts[property.verdict] += 1;
    const count = data.properties.length;
    $("summary").textContent = count + (count === 1 ? " property" : " properties") + ": " +
      counts.HOLDS + " hold, " + counts.VIOLATED + " violated, " +
      counts.UNKNOWN + " unknown";
    $("footer").textContent = "Made by " + data.tool + " from " +
      data.files.map((file) => file.name).join(", ") + ".";
  }

  function showProperties() {
    const body = $("property-table").tBodies[0];
    data.properties.forEach((property, index) => {
      const row = element("tr");
      row.id = "property-" + index;
      row.appendChild(element("td", "name", property.name));
      const verdict = element("td");
      verdict.appendChild(element("span", "verdict " + property.verdict, property.verdict));
      if (property.reason) verdict.appendChild(element("div", "reason", property.reason));
      if (property.fairness) verdict.appendChild(element("div", "reason fairness", property.fairness));
      for (const text of property.assumes || []) {
        verdict.appendChild(element("div", "reason assumes", "assumes: " + text));
      }
      row.appendChild(verdict);
      const formula = element("td");
      if (property.pattern) {
        formula.appendChild(element("code", "pattern", property.pattern));
        formula.appendChild(element("div", "reason", "LTL: " + property.formula));
      } else {
        formula.appendChild(element("code", null, property.formula));
      }
      if (property.atoms_text) formula.appendChild(element("div", "reason atoms", property.atoms_text));
      row.appendChild(formula);
      const stats = property.stats;
      row.appendChild(element("td", "number", stats.product_states.toLocaleString("en")));
      row.appendChild(element("td", "number", stats.transitions.toLocaleString("en")));
      row.appendChild(element("td", "number", stats.max_depth.toLocaleString("en")));
      row.appendChild(element("td", "number", seconds(stats.seconds)));
      row.title = "states stored " + stats.product_states + ", program states " +
        stats.model_states + ", transitions " + stats.transitions + ", deepest path " +
        stats.max_depth + ", " + stats.states_per_second + " states/s, states without successor " +
        stats.deadlocks;
      const action = element("td");
      if (property.trace) {
        const button = element("button", "show-trace", "counterexample");
        button.type = "button";
        button.addEventListener("click", () => select(index));
        action.appendChild(button);
      }
      row.appendChild(action);
      body.appendChild(row);
    });
  }

  // --- choosing a counterexample ---------------------------------------------

  function select(index) {
    const property = data.properties[index];
    player.property = property;
    player.steps = property.trace.steps;
    player.views.clear();
    player.marked = [];
    player.file = null;
    $("source").textContent = "";
    for (const row of document.querySelectorAll("#property-table tr.selected")) {
      row.classList.remove("selected");
    }
    $("property-" + index).classList.add("selected");
    $("counterexample").hidden = false;
    $("trace-name").textContent = property.name;
    $("trace-formula").textContent = property.formula +
      (property.atoms_text ? "  [" + property.atoms_text + "]" : "");
    $("trace-pattern").textContent = property.pattern || "";
    $("trace-pattern-line").hidden = !property.pattern;
    $("trace-shape").textContent = traceShape(property.trace);
    $("slider").max = String(player.steps.length);
    showFileTabs();
    showTimeline(property.trace);
    goTo(0);
  }

  // "5 steps to the error: uncaught ERR_DIVZERO: ... (step 5), reading n = 0 (initial value)."
  function errorText(total, error) {
    const reads = error.reads.map((read) => read.name + " = " + read.value + " (" + read.origin + ")");
    return plural(total, "step") + " to the error: " + error.message + " (step " + error.step + ")" +
      (reads.length ? ", reading " + reads.join(", ") : "") + ".";
  }

  // "23 steps, then any run: every run that goes on from this step violates the property."
  function badPrefixText(total, error) {
    return plural(total, "step") + ", then any run: " + error.message + " (no loop needed).";
  }

  function traceShape(trace) {
    const total = trace.steps.length;
    if (trace.loop_start === null && trace.error && trace.error.bad_prefix)
      return badPrefixText(total, trace.error);
    if (trace.loop_start === null && trace.error) return errorText(total, trace.error);
    if (trace.loop_start === null) return plural(total, "step") + " to the state that violates it.";
    const prefix = trace.loop_start - 1;
    return plural(prefix, "step") + ", then a loop of " +
      plural(trace.closing - trace.loop_start, "step") + " (steps " + trace.loop_start + "–" +
      trace.closing + ") that repeats forever.";
  }

  // --- stepping -------------------------------------------------------------------

  function goTo(position) {
    const last = player.steps.length - 1;
    position = Math.max(0, Math.min(last, position));
    player.position = position;
    const step = player.steps[position];
    const trace = player.property.trace;
    $("step-counter").textContent = "step " + step.index + " of " + player.steps.length;
    $("slider").value = String(position + 1);
    $("first").disabled = $("prev").disabled = position === 0;
    $("last").disabled = $("next").disabled = position === last;
    $("loop-badge").hidden = !(trace.loop_start !== null && step.index >= trace.loop_start);
    $("counterexample").dataset.step = String(step.index);
    showStep(step, trace);
    showSourceAt(step);
    moveTimelineCursor(position);
  }

  function showStep(step, trace) {
    const here = step.location ? step.location : innermost(step);
    $("step-location").textContent = step.kind === "initial" ? "initial state" :
      (here ? where(here.file, here.line) : "");
    $("step-source").textContent = step.source || "";
    $("step-note").textContent = stepNote(step, trace);
    showStack(step);
    showValues($("inputs"), Object.entries(step.inputs).map(([name, value]) => [name, value, null]),
      "none");
    showValues($("changes"), Object.entries(step.changes).map(([name, value]) =>
      [name, value === null ? "(no longer exists)" : value, step.kind === "initial" ? null :
        step.was[name]]), "nothing changed");
    const output = player.steps.slice(0, player.position + 1)
      .filter((s) => s.output !== null).map((s) => s.output);
    $("flexpendant").textContent = output.length ? output.join("") : "(nothing written yet)";
    $("flexpendant").classList.toggle("empty", !output.length);
  }

  function stepNote(step, trace) {
    if (step.kind === "initial") {
      return "Before the first statement; every value is listed below, and the program starts at the highlighted line.";
    }
    if (trace.closing === step.index) {
      return "The loop closes: this step leads back to the state of step " + trace.loop_start +
        ", and steps " + trace.loop_start + "–" + step.index + " repeat forever.";
    }
    if (trace.loop_start === step.index) return "The repeating loop starts here.";
    return "";
  }

  // The stack holds every task's routines (task by task, outermost first); the running one
  // is the task whose innermost routine is at the step's line (at the start: the first task).
  function tasks(stack) {
    const groups = [];
    for (const frame of stack) {
      const last = groups[groups.length - 1];
      if (last && last[0].task === frame.task) last.push(frame);
      else groups.push([frame]);
    }
    return groups;
  }

  function runningTask(step, groups = tasks(step.stack)) {
    const here = step.location;
    const found = here && groups.find((group) => {
      const top = group[group.length - 1];
      return top.file === here.file && top.line === here.line;
    });
    return found || groups[0] || [];
  }

  function innermost(step) {
    const group = runningTask(step);
    return group.length ? group[group.length - 1] : null;
  }

  function showStack(step) {
    const list = $("call-stack");
    list.textContent = "";
    const groups = tasks(step.stack);
    const running = runningTask(step, groups);
    const others = groups.filter((group) => group !== running);
    for (const group of [running, ...others]) {
      for (const frame of group.slice().reverse()) {
        const task = frame.task ? frame.task + ": " : "";
        const item = element("li", group === running ? null : "other-task",
          task + frame.routine + "  " + where(frame.file, frame.line));
        item.title = "show " + where(frame.file, frame.line);
        item.addEventListener("click", () => showLine(frame.file, frame.line));
        list.appendChild(item);
      }
    }
    if (!step.stack.length) list.appendChild(element("li", "note", "no active routine"));
  }

  function showValues(table, rows, empty) {
    const body = table.tBodies[0];
    body.textContent = "";
    for (const [name, value, was] of rows) {
      const row = element("tr");
      row.appendChild(element("td", "name", name));
      const cell = element("td", "value", value);
      if (was !== null && was !== undefined) cell.appendChild(element("span", "was", "  (was " + was + ")"));
      row.appendChild(cell);
      body.appendChild(row);
    }
    if (!rows.length) {
      const row = element("tr");
      row.appendChild(element("td", "empty", empty));
      body.appendChild(row);
    }
  }

  // --- source view -------------------------------------------------------------

  function showFileTabs() {
    const tabs = $("file-tabs");
    tabs.textContent = "";
    for (const name of files.keys()) {
      const tab = element("button", null, baseName(name));
      tab.type = "button";
      tab.title = name;
      tab.dataset.file = name;
      tab.addEventListener("click", () => showFile(name));
      tabs.appendChild(tab);
    }
  }

  function visitedLines(file) {
    const lines = new Set();
    for (const step of player.steps) {
      if (step.location && step.location.file === file) lines.add(step.location.line);
    }
    return lines;
  }

  function fileView(name) {
    let view = player.views.get(name);
    if (view) return view;
    const container = element("div", "file");
    const visited = visitedLines(name);
    const lines = (files.get(name) || []).map((text, index) => {
      const line = element("div", "line" + (visited.has(index + 1) ? " visited" : ""));
      line.dataset.line = String(index + 1);
      const dead = unreached.get(name + ":" + (index + 1));
      if (dead !== undefined) {
        line.classList.add("unreached");
        line.title = dead;
      }
      line.appendChild(element("span", "number", String(index + 1)));
      line.appendChild(element("span", "text", text));
      container.appendChild(line);
      return line;
    });
    view = {element: container, lines: lines};
    player.views.set(name, view);
    $("source").appendChild(container);
    return view;
  }

  function showFile(name) {
    if (!files.has(name)) return null;
    const view = fileView(name);
    for (const [other, otherView] of player.views) otherView.element.hidden = other !== name;
    for (const tab of $("file-tabs").children) tab.classList.toggle("active", tab.dataset.file === name);
    player.file = name;
    return view;
  }

  function showSourceAt(step) {
    for (const line of player.marked) line.classList.remove("current", "caller");
    player.marked = [];
    const here = step.location || innermost(step);
    if (!here || !files.has(here.file)) return;
    const view = showFile(here.file);
    for (const frame of runningTask(step).slice(0, -1)) {
      mark(frame.file === here.file ? view.lines[frame.line - 1] : null, "caller");
    }
    const current = view.lines[here.line - 1];
    mark(current, "current");
    scrollTo(current);
  }

  function mark(line, className) {
    if (!line) return;
    line.classList.add(className);
    player.marked.push(line);
  }

  function showLine(file, line) {
    const view = showFile(file);
    if (view) scrollTo(view.lines[line - 1]);
  }

  function scrollTo(line) {
    if (!line) return;
    const pane = $("source");
    pane.scrollTop = Math.max(0, line.offsetTop - pane.clientHeight / 2 + line.offsetHeight / 2);
  }

  // --- timeline --------------------------------------------------------------------

  function showTimeline(trace) {
    const steps = trace.steps;
    const rows = trace.timeline.slice();
    if (steps.some((step) => step.output !== null)) {
      rows.push({name: "FlexPendant output", kind: "marker",
                 values: steps.map((step) => step.output)});
    }
    const width = steps.length * COLUMN;
    const header = 2 * ROW;               // the loop's bracket, then the step numbers
    const height = header + ROW * rows.length;
    const box = svg("svg", {width: width, height: height, viewBox: "0 0 " + width + " " + height});
    if (trace.loop_start !== null) {
      const x = (trace.loop_start - 1) * COLUMN;
      box.appendChild(svg("rect", {class: "loop", x: x, y: 0, width: width - x, height: height}));
      box.appendChild(svg("text", {class: "loop-label", x: x + 4, y: ROW - 8},
        "\u21BA loop: steps " + trace.loop_start + "\u2013" + trace.closing +
        ", then step " + trace.loop_start + " again"));
    }
    steps.forEach((step, index) => {
      const x = index * COLUMN;
      box.appendChild(svg("line", {class: "grid", x1: x, y1: ROW, x2: x, y2: height}));
      box.appendChild(svg("text", {class: "axis", x: x + COLUMN / 2, y: header - 8,
                                   "text-anchor": "middle"}, String(step.index)));
    });
    rows.forEach((row, number) => drawRow(box, row, header + ROW * number));
    box.appendChild(svg("rect", {id: "timeline-now", class: "now", x: 0, y: 0, width: COLUMN,
                                 height: height}));
    steps.forEach((step, index) => {
      const column = svg("rect", {class: "column", x: index * COLUMN, y: 0, width: COLUMN,
                                  height: height, "data-step": step.index});
      column.appendChild(svg("title", {}, "step " + step.index +
        (step.location ? "  " + where(step.location.file, step.location.line) : "")));
      column.addEventListener("click", () => goTo(index));
      box.appendChild(column);
    });
    const labels = element("div", "labels");
    labels.appendChild(element("div", null, trace.loop_start !== null ? "loop" : ""));
    labels.appendChild(element("div", null, "step"));
    for (const row of rows) {
      const label = element("div", null, row.name);
      label.title = row.name + (row.kind === "marker" ? "" : " (" + row.kind + ")");
      labels.appendChild(label);
    }
    const waves = element("div", "waves");
    waves.appendChild(box);
    const timeline = $("timeline");
    timeline.textContent = "";
    timeline.appendChild(labels);
    timeline.appendChild(waves);
  }

  function drawRow(box, row, top) {
    if (row.kind === "num") drawBus(box, row.values, top);
    else if (row.kind === "marker") drawMarkers(box, row.values, top);
    else drawWave(box, row.values, top, row.kind === "digital" ? "1" : "TRUE");
  }

  function drawWave(box, values, top, high) {
    let path = "";
    let previous = null;
    values.forEach((value, index) => {
      if (value === null) { previous = null; return; }
      const x = index * COLUMN;
      const y = value === high ? top + 5 : top + ROW - 5;
      path += previous === null ? "M" + x + " " + y : (previous !== y ? " L" + x + " " + y : "");
      path += " L" + (x + COLUMN) + " " + y;
      previous = y;
    });
    if (path) box.appendChild(svg("path", {class: "wave", d: path}));
  }

  function drawBus(box, values, top) {
    let start = 0;
    values.forEach((value, index) => {
      if (index + 1 < values.length && values[index + 1] === value) return;
      if (value !== null) busSegment(box, value, start * COLUMN, (index + 1) * COLUMN, top);
      start = index + 1;
    });
  }

  function busSegment(box, value, x0, x1, top) {
    const y0 = top + 4, y1 = top + ROW - 4, middle = top + ROW / 2;
    const points = [[x0 + 1, middle], [x0 + 4, y0], [x1 - 4, y0], [x1 - 1, middle],
                    [x1 - 4, y1], [x0 + 4, y1]].map((p) => p.join(",")).join(" ");
    const shape = svg("polygon", {class: "bus", points: points});
    shape.appendChild(svg("title", {}, value));
    box.appendChild(shape);
    const room = Math.floor((x1 - x0 - 10) / 6.6);
    if (room < 1) return;
    const shown = value.length <= room ? value : value.slice(0, Math.max(room - 1, 1)) + "\u2026";
    box.appendChild(svg("text", {class: "value", x: x0 + 6, y: middle + 4}, shown));
  }

  function drawMarkers(box, values, top) {
    values.forEach((value, index) => {
      if (value === null) return;
      const dot = svg("circle", {class: "marker", cx: index * COLUMN + COLUMN / 2,
                                 cy: top + ROW / 2, r: 4});
      dot.appendChild(svg("title", {}, value));
      box.appendChild(dot);
    });
  }

  function moveTimelineCursor(position) {
    const now = $("timeline-now");
    if (now) now.setAttribute("x", String(position * COLUMN));
    const waves = document.querySelector("#timeline .waves");
    if (!waves) return;
    const x = position * COLUMN;
    if (x < waves.scrollLeft || x + COLUMN > waves.scrollLeft + waves.clientWidth) {
      waves.scrollLeft = Math.max(0, x - waves.clientWidth / 2);
    }
  }

  // --- controls ----------------------------------------------------------------------

  function step(delta) {
    if (player.property) goTo(player.position + delta);
  }

  $("first").addEventListener("click", () => goTo(0));
  $("prev").addEventListener("click", () => step(-1));
  $("next").addEventListener("click", () => step(1));
  $("last").addEventListener("click", () => goTo(player.steps.length - 1));
  $("slider").addEventListener("input", (event) => goTo(Number(event.target.value) - 1));
  document.addEventListener("keydown", (event) => {
    if (!player.property || event.altKey || event.ctrlKey || event.metaKey) return;
    if (event.target === $("slider")) return;        // the slider moves itself
    const moves = {ArrowLeft: () => step(-1), ArrowRight: () => step(1),
                   Home: () => goTo(0), End: () => goTo(player.steps.length - 1)};
    const move = moves[event.key];
    if (move) {
      event.preventDefault();
      move();
    }
  });

  showSummary();
  showProperties();
  const firstViolated = data.properties.findIndex((property) => property.trace);
  if (firstViolated >= 0) select(firstViolated);
})();
