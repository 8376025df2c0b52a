"""``rapidmc check --html FILE``: the report page, opened in headless Chromium.

The browser tests open the sorting cell's report (program B, whose P2 is
violated) and a small counter cell with FlexPendant dialogue, step through
the counterexample with the buttons, the arrow keys, the slider and the
timeline, and compare what the page shows with the JSON report of the same
run.  Without Chromium, chromedriver or selenium they skip, unless
RAPIDMC_REQUIRE_BROWSER=1 (CI), where they fail.  RAPIDMC_REPORT_SCREENSHOT
names a PNG file to keep a screenshot of the sorting cell's page in.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rapidmc.check import check_property
from rapidmc.report.html import timeline_rows
from rapidmc.check.trace import CallFrame, Change, TraceStep, build_trace
from test_engine_models import NOT_INFINITELY_OFTEN_P
from test_report import Cell, CellDescriber

ROOT = Path(__file__).resolve().parent.parent
SORTER = ["case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
          "--ltl", "specs/sorter.ltl"]
COUNTER = ["tests/html_report/counter.mod", "--ltl", "tests/html_report/counter.ltl",
           "--tp-answers", "1,2"]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
CHROMEDRIVER = shutil.which("chromedriver")


def rapidmc(*arguments: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "rapidmc", *arguments], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def report(tmp_path_factory, name: str, program: list[str]) -> tuple[Path, dict]:
    """The page and the JSON document of one ``check`` run."""
    page = tmp_path_factory.mktemp(name) / "report.html"
    done = rapidmc("check", *program, "--quiet", "--format", "json", "--html", str(page))
    assert done.returncode == 1, done.stderr
    return page, json.loads(done.stdout)


@pytest.fixture(scope="module")
def sorter(tmp_path_factory):
    return report(tmp_path_factory, "sorter", SORTER)


@pytest.fixture(scope="module")
def counter(tmp_path_factory):
    return report(tmp_path_factory, "counter", COUNTER)


def violated(document: dict, name: str) -> list[dict]:
    """Every step of a property's trace in order, the closing step last."""
    (entry,) = [p for p in document["properties"] if p["name"] == name]
    trace = entry["trace"]
    return [*trace["prefix"], *trace["cycle"], *([trace["closing"]] if trace["closing"] else [])]


# --- without a browser: the data behind the timeline, failures, the file itself ----------


def steps_of(*changes: dict) -> list[TraceStep]:
    return [TraceStep(index, "transition", None,
                      tuple(Change(name, None, new) for name, new in step.items()))
            for index, step in enumerate(changes, start=1)]


TIMELINE_CASES = [
    # (what, the changes of each step, expected rows as (name, kind))
    ("a 0/1 signal is a digital row even when it never changes",
     [{"signal DO1": "0"}, {}], [("signal DO1", "digital")]),
    ("bool and num data that change are rows; values that stay are not",
     [{"x": "1", "ok": "FALSE", "same": "3"}, {"x": "2.5", "ok": "TRUE"}],
     [("x", "num"), ("ok", "bool")]),
    ("digital signals come first",
     [{"n": "0", "signal S": "1"}, {"n": "1"}], [("signal S", "digital"), ("n", "num")]),
    ("an analog signal is a num row when it changes",
     [{"signal AI": "0"}, {"signal AI": "4.5"}], [("signal AI", "num")]),
    ("strings and records are not drawn",
     [{"s": '"a"', "p": "[1,2,3]"}, {"s": '"b"', "p": "[4,5,6]"}], []),
]


@pytest.mark.parametrize("what, changes, expected", TIMELINE_CASES,
                         ids=[case[0] for case in TIMELINE_CASES])
def test_timeline_rows(what, changes, expected):
    rows = timeline_rows(steps_of(*changes))
    assert [(row["name"], row["kind"]) for row in rows] == expected


def test_timeline_values_accumulate_and_leave_gaps_where_an_item_is_gone():
    steps = [TraceStep(1, "initial", None, (Change("x", None, "1"),)),
             TraceStep(2, "transition", None, (Change("x", "1", None),)),
             TraceStep(3, "transition", None, (Change("x", None, "2"),)),
             TraceStep(4, "transition", None, ())]
    assert timeline_rows(steps) == [{"name": "x", "kind": "num", "values": ["1", None, "2", "2"]}]


class CellWithStack(CellDescriber):
    """The toy cell of test_report, whose one routine is at line 11 + pc."""

    def describe_stack(self, state):
        return (CallFrame("main", "cell.mod", 11 + state[0]),)


def test_each_step_carries_the_stack_its_statement_runs_in():
    result = check_property(Cell(), NOT_INFINITELY_OFTEN_P, lambda state: int(state[1] == 2))
    trace = build_trace(result, CellWithStack())
    steps = [*trace.prefix, *trace.cycle, trace.closing]
    assert steps[0].stack == (CallFrame("main", "cell.mod", 11),)     # where the run starts
    assert all(step.stack == (CallFrame("main", "cell.mod", step.transition.line),)
               for step in steps[1:])
    assert all(step.stack == () for step in build_trace(result, CellDescriber()).prefix)


@pytest.mark.parametrize("target, why", [("no-such-folder/report.html", "does not exist"),
                                         (".", "is a directory")])
def test_an_html_path_that_cannot_be_written_is_refused_before_the_search(target, why):
    done = rapidmc("check", *COUNTER, "--quiet", "--html", target)
    assert done.returncode == 2
    assert "[RMC520]" in done.stderr and why in done.stderr
    assert "Traceback" not in done.stderr and done.stdout == ""


def test_the_page_is_one_file_that_names_no_address_to_load(counter):
    page, _ = counter
    text = page.read_text(encoding="utf-8")
    assert "default-src 'none'" in text           # the browser refuses any request
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:|//)""", text, re.I)
    data = text.split('id="report-data">', 1)[1].split("</script>", 1)[0]
    assert "<" not in data                        # program text cannot end the data early
    assert json.loads(data)["properties"][2]["name"] == "lamp_off"


# --- in Chromium ---------------------------------------------------------------------


def require_browser() -> None:
    missing = [name for name, path in (("chromium", CHROMIUM), ("chromedriver", CHROMEDRIVER))
               if path is None]
    try:
        import selenium  # noqa: F401
    except ImportError:
        missing.append("the selenium package")
    if missing:
        if os.environ.get("RAPIDMC_REQUIRE_BROWSER") == "1":
            pytest.fail(f"{', '.join(missing)} missing but RAPIDMC_REQUIRE_BROWSER=1")
        pytest.skip(f"no browser to test the page in ({', '.join(missing)} missing; "
                    "Debian packages chromium, chromium-driver)")


@pytest.fixture(scope="module")
def browser():
    require_browser()
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu",
                     "--disable-dev-shm-usage", "--window-size=1400,1400"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"performance": "ALL", "browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    yield driver
    driver.quit()


class Page:
    """The report as the browser shows it: what the reader sees, read from the DOM."""

    def __init__(self, driver, path: Path):
        from selenium.webdriver.common.by import By
        self.driver = driver
        self.by = By
        driver.get(path.as_uri())
        assert self.errors() == []

    def errors(self) -> list[str]:
        return [entry["message"] for entry in self.driver.get_log("browser")
                if entry["level"] == "SEVERE"]

    def find(self, css: str):
        return self.driver.find_element(self.by.CSS_SELECTOR, css)

    def click(self, css: str) -> None:
        element = self.find(css)
        self.driver.execute_script("arguments[0].scrollIntoView({block: 'center'})", element)
        element.click()

    def texts(self, css: str) -> list[str]:
        return self.driver.execute_script(
            "return [...document.querySelectorAll(arguments[0])].map((e) => e.textContent)", css)

    def keys(self, *keys: str, target: str = "body") -> None:
        self.find(target).send_keys(*keys)

    def shown(self) -> dict:
        """The current step: counter, statement, highlighted line, stack, inputs, changes."""
        return self.driver.execute_script("""
            const text = (css) => [...document.querySelectorAll(css)].map((e) => e.textContent);
            const current = document.querySelector('.source .file:not([hidden]) .line.current');
            return {
              counter: document.getElementById('step-counter').textContent,
              step: Number(document.getElementById('counterexample').dataset.step),
              source: document.getElementById('step-source').textContent,
              note: document.getElementById('step-note').textContent,
              line: current ? Number(current.dataset.line) : null,
              lineText: current ? current.querySelector('.text').textContent.trim() : null,
              callers: text('.source .file:not([hidden]) .line.caller .text').map((t) => t.trim()),
              file: document.querySelector('#file-tabs .active')?.title ?? null,
              stack: text('#call-stack li'),
              inputs: text('#inputs td.name'),
              changes: [...document.querySelectorAll('#changes tr')]
                .filter((row) => row.querySelector('td.name'))
                .map((row) => [row.querySelector('td.name').textContent,
                               row.querySelector('td.value').textContent]),
              flexpendant: document.getElementById('flexpendant').textContent,
              loopBadge: !document.getElementById('loop-badge').hidden,
              nextEnabled: !document.getElementById('next').disabled,
              prevEnabled: !document.getElementById('prev').disabled,
            };""")


def test_the_page_lists_every_property_with_verdict_formula_and_statistics(browser, sorter):
    path, document = sorter
    page = Page(browser, path)
    rows = page.driver.execute_script(
        "return [...document.querySelectorAll('#property-table tbody tr')]"
        ".map((row) => [...row.cells].slice(0, 4).map((cell) => cell.textContent))")
    assert rows == [[p["name"], p["verdict"], p["formula"], f"{p['stats']['product_states']:,}"]
                    for p in document["properties"]]
    assert page.find("#summary").text == "5 properties: 3 hold, 2 violated, 0 unknown"
    assert page.find("#trace-name").text == "P2"             # the first violated property


def test_a_pattern_is_shown_beside_its_formula(browser, tmp_path_factory):
    path, document = report(tmp_path_factory, "patterns",
                            SORTER[:-1] + ["specs/sorter_patterns.ltl"])
    page = Page(browser, path)
    cells = page.texts("#property-table tbody tr:nth-child(4) td:nth-child(3) > *")
    p2 = document["properties"][3]
    assert p2["name"] == "P2" and cells == [p2["pattern"], "LTL: " + p2["formula"]]
    assert page.find("#trace-pattern").text == p2["pattern"]
    assert page.find("#trace-formula").text == p2["formula"]


def test_next_steps_through_the_counterexample_as_the_json_report_has_it(browser, sorter):
    path, document = sorter
    steps = violated(document, "P2")
    page = Page(browser, path)
    for number, step in enumerate(steps, start=1):
        shown = page.shown()
        assert shown["counter"] == f"step {number} of {len(steps)}"
        assert shown["step"] == step["index"] == number
        assert shown["source"] == (step["source"] or "")
        assert [name for name, _ in shown["changes"]] == list(step["changes"])
        assert shown["inputs"] == list(step["inputs"])
        if step["location"]:
            assert shown["file"] == step["location"]["file"]
            assert (shown["line"], shown["lineText"]) == (step["location"]["line"], step["source"])
        assert shown["prevEnabled"] == (number > 1)
        assert shown["nextEnabled"] == (number < len(steps))
        if number < len(steps):
            page.click("#next")
    assert "loop closes" in page.shown()["note"]
    page.click("#prev")
    assert page.shown()["step"] == len(steps) - 1
    assert page.errors() == []


def test_arrow_keys_home_and_end_move_through_the_steps(browser, sorter):
    from selenium.webdriver.common.keys import Keys
    path, document = sorter
    last = len(violated(document, "P2"))
    page = Page(browser, path)
    page.keys(Keys.ARROW_RIGHT, Keys.ARROW_RIGHT, Keys.ARROW_RIGHT)
    assert page.shown()["step"] == 4
    page.keys(Keys.ARROW_LEFT)
    assert page.shown()["step"] == 3
    page.keys(Keys.END)
    assert page.shown()["step"] == last
    page.keys(Keys.ARROW_RIGHT)                      # stays on the last step
    assert page.shown()["step"] == last
    page.keys(Keys.HOME)
    assert page.shown()["step"] == 1


def test_the_slider_moves_one_step_per_key(browser, sorter):
    from selenium.webdriver.common.keys import Keys
    path, _ = sorter
    page = Page(browser, path)
    page.keys(Keys.ARROW_RIGHT * 5, target="#slider")
    assert page.shown()["step"] == 6
    assert page.find("#slider").get_attribute("value") == "6"


def test_clicking_a_timeline_column_jumps_to_that_step_and_the_loop_is_marked(browser, sorter):
    path, document = sorter
    (entry,) = [p for p in document["properties"] if p["name"] == "P2"]
    loop_start = entry["trace"]["loop_start"]
    page = Page(browser, path)
    labels = page.texts("#timeline .labels div")
    signals = [f"signal {name}" for name in
               ("C_IN", "S_1", "S_2", "S_3", "S_4", "C_OUT", "GRIPPER")]
    assert labels[2:2 + len(signals)] == signals
    assert page.find("#timeline .loop-label").text.startswith(f"\u21ba loop: steps {loop_start}")
    page.click(f'#timeline rect.column[data-step="{loop_start}"]')
    shown = page.shown()
    assert shown["step"] == loop_start and shown["loopBadge"]
    assert shown["note"] == "The repeating loop starts here."
    assert page.find("#timeline-now").get_attribute("x") == str((loop_start - 1) * 24)
    page.click('#timeline rect.column[data-step="2"]')
    assert page.shown()["step"] == 2 and not page.shown()["loopBadge"]
    screenshot = os.environ.get("RAPIDMC_REPORT_SCREENSHOT")
    if screenshot:
        page.click(f'#timeline rect.column[data-step="{first_step(document, "SetDO do_grip, 1;")}"]')
        page.driver.execute_script("window.scrollTo(0, 0)")
        assert page.driver.save_screenshot(screenshot)


def first_step(document: dict, source: str) -> int:
    return next(s["index"] for s in violated(document, "P2") if s["source"] == source)


def test_inside_a_procedure_the_stack_shows_the_caller_and_its_call_line(browser, sorter):
    path, document = sorter
    number = first_step(document, "SetDO do_grip, 1;")
    page = Page(browser, path)
    page.click(f'#timeline rect.column[data-step="{number}"]')
    shown = page.shown()
    assert shown["lineText"] == "SetDO do_grip, 1;"
    (callee, caller) = shown["stack"]
    assert callee == f"Grip  sorter_b.mod:{shown['line']}"
    assert caller.startswith("main  sorter_b.mod:")
    assert shown["callers"] == ["Grip;"]
    assert ["signal GRIPPER", "1  (was 0)"] in shown["changes"]


def test_flexpendant_output_inputs_and_num_rows_of_the_counter_cell(browser, counter):
    path, document = counter
    steps = violated(document, "lamp_off")
    write = next(s["index"] for s in steps if (s["source"] or "").startswith("TPWrite"))
    page = Page(browser, path)
    assert page.shown()["flexpendant"] == "(nothing written yet)"
    labels = page.texts("#timeline .labels div")
    # Add.amount is always 1 where it exists: no row
    assert labels[2:] == ["signal LAMP", "count", "full", "answer", "FlexPendant output"]
    page.click(f'#timeline rect.column[data-step="{write}"]')
    shown = page.shown()
    prompts = sum(1 for s in steps[:write] if s["output"] == "How many parts?\n")
    assert shown["flexpendant"] == "How many parts?\n" * prompts + "</script><b>full</b> at 2\n"
    assert [frame.split()[0] for frame in shown["stack"]] == ["Add", "main"]
    reads = next(s["index"] for s in steps if s["inputs"])
    page.click(f'#timeline rect.column[data-step="{reads}"]')
    assert page.shown()["inputs"] == ["TPReadNum"]
    assert page.errors() == []


def test_the_page_makes_no_network_request(browser, counter):
    path, _ = counter
    page = Page(browser, path)
    addresses = page.driver.execute_script(
        "return [...document.querySelectorAll('[src], [href]')]"
        ".map((e) => e.getAttribute('src') || e.getAttribute('href'))")
    assert not [a for a in addresses if re.match(r"\s*(https?:)?//", a)]
    requested = [json.loads(entry["message"])["message"]["params"]["request"]["url"]
                 for entry in page.driver.get_log("performance")
                 if '"Network.requestWillBeSent"' in entry["message"]]
    assert requested and all(url.startswith(("file:", "data:", "about:")) for url in requested)


def test_without_a_violation_the_page_shows_only_the_table(browser, tmp_path):
    require_browser()
    path = tmp_path / "holds.html"
    done = rapidmc("check", "tests/html_report/counter.mod", "--tp-answers", "1,2", "--quiet",
                   "--formula", 'reads: G F "answer > 0"', "--html", str(path))
    assert done.returncode == 0, done.stderr
    page = Page(browser, path)
    assert not page.find("#counterexample").is_displayed()
    assert page.find("#summary").text == "3 properties: 3 hold, 0 violated, 0 unknown"


def test_with_several_tasks_the_stack_shows_the_running_task_first(browser, tmp_path):
    from test_tasks import COUNTER as TASK_COUNTER
    require_browser()
    for name in "ab":
        (tmp_path / f"{name}.mod").write_text(TASK_COUNTER.format(n=name.upper()))
    path = tmp_path / "tasks.html"
    done = rapidmc("check", "a.mod", "--add-task", "b.mod", "--formula",
                   'all_counted: F G "count = 4"', "--quiet", "--format", "json",
                   "--html", str(path), cwd=tmp_path)
    steps = violated(json.loads(done.stdout), "all_counted")
    in_b = next(s for s in steps if s["location"] and s["location"]["file"] == "b.mod")
    page = Page(browser, path)
    page.click(f'#timeline rect.column[data-step="{in_b["index"]}"]')
    shown = page.shown()
    assert shown["file"] == "b.mod" and shown["lineText"] == in_b["source"]
    (running, other) = shown["stack"]
    # each frame names its task as the data do (TASK2.count): the added task b is TASK2
    assert running == f"TASK2: main  b.mod:{in_b['location']['line']}"
    assert other.startswith("TASK1: main  a.mod:")


def test_with_several_tasks_the_table_says_fairness_was_assumed(browser, tmp_path):
    require_browser()
    case = ROOT / "tests" / "check" / "tasks_fairness"
    path = tmp_path / "fair.html"
    done = rapidmc("check", str(case / "prog.mod"), "--add-task", str(case / "b.mod"),
                   "--ltl", str(case / "props.ltl"), "--quiet", "--html", str(path))
    assert done.returncode == 1, done.stderr           # some of its properties are violated
    page = Page(browser, path)
    notes = page.texts("#properties .fairness")
    assert notes and all(n.startswith("assuming weak fairness between the tasks main task")
                         for n in notes)


def test_a_path_to_an_error_says_the_error_and_unreached_stretches_are_shaded(browser, tmp_path):
    """tests/counterexamples/many_unreached: a division by zero at line 74 after a branch
    (lines 10-72) and three routines that never run, only the branch calling them: one
    warning (one cause), every place of which is shaded."""
    require_browser()
    path = tmp_path / "error.html"
    done = rapidmc("check", "tests/counterexamples/many_unreached/prog.mod", "--quiet",
                   "--html", str(path))
    assert done.returncode == 1, done.stderr
    page = Page(browser, path)
    page.click("#property-0 button.show-trace")
    assert page.find("#trace-shape").text == (
        "3 steps to the error: uncaught ERR_DIVZERO: division by zero (step 3), reading "
        "total = 0 (initial value).")
    shaded = [int(n) for n in page.driver.execute_script(
        "return [...document.querySelectorAll('.source .line.unreached')]"
        ".map((line) => line.dataset.line)")]
    assert set(range(10, 73)) <= set(shaded) and 74 not in shaded and 9 not in shaded
    assert set(range(77, 119)) | set(range(163, 205)) <= set(shaded)


def test_a_bad_prefix_says_that_any_run_goes_on_and_shows_no_loop(browser, tmp_path):
    """tests/check/ltl_safety_unbounded_counter: G !(gripper_open & moving) broken at step 23
    of a loop that counts for ever: a finite counterexample, no loop."""
    require_browser()
    from selenium.webdriver.common.keys import Keys
    folder = ROOT / "tests" / "check" / "ltl_safety_unbounded_counter"
    path = tmp_path / "prefix.html"
    done = rapidmc("check", "prog.mod", "--ltl", "props.ltl", "--max-states", "3000", "--quiet",
                   "--html", str(path), cwd=folder)
    assert done.returncode == 1, done.stderr
    page = Page(browser, path)
    page.click("#property-2 button.show-trace")
    assert page.find("#trace-shape").text == (
        "23 steps, then any run: every run that goes on from this step violates the property "
        "(no loop needed).")
    page.keys(Keys.END)
    shown = page.shown()
    assert shown["step"] == 23 and shown["lineText"] == "gripper_open := TRUE;"
    assert not shown["loopBadge"]
