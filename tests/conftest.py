"""The ``engine_independent`` marker, and the probe that keeps it true.

``.ci/run`` runs the suite twice: with the compiled search core, then with the core removed
and ``RAPIDMC_ENGINE=python``.  The second run only has something to say about tests whose
outcome can depend on the engine; it leaves out the modules marked
``pytestmark = pytest.mark.engine_independent`` (``-m "not engine_independent"``).

The rule (docs/ci.md, "rapidmc's own CI"): a module may carry the mark only when none of its
tests consults the engine, that is calls a function of ``rapidmc.check.native`` (every search
asks it for its state table or its loop; ``--engine``, ``--version`` and the checks for the
core ask it too) or the packed table's offer, neither in the test nor in its fixtures nor
when the module is imported.  The probe below wraps those functions: a marked test that
consults the engine fails, in every run, and names the functions it called.  The probe sees
this process only; a marked module that starts processes says why their engine does not
follow the run's (STARTED_PROCESSES in tests/test_engine_independence.py).
"""
from __future__ import annotations

import functools
import sys

import pytest

from rapidmc.check import native
from rapidmc.model.packed import table as packed

MARK = "engine_independent"
# the functions through which anything learns or sets the engine, or reads whether the core
# is built: rapidmc.check.native's, and the packed table's offer (the one reader of the core
# outside rapidmc.check)
CONSULTING = {native: ("engine", "available", "description", "native_search", "state_table",
                       "engine_of", "use_engine"),
              packed: ("packed_table",)}


class EngineProbe:
    """Which engine-consulting functions were called since ``start``."""

    def __init__(self) -> None:
        self.called: list[str] = []

    def start(self) -> None:
        self.called = []

    def take(self) -> list[str]:
        called, self.called = sorted(set(self.called)), []
        return called

    def wrap(self, function):
        @functools.wraps(function)
        def consulted(*arguments, **keywords):
            self.called.append(function.__name__)
            return function(*arguments, **keywords)
        return consulted

    def install(self) -> None:
        """Wrap the functions where they are defined and in every rapidmc module that
        imported them by name already (modules imported later take the wrapped ones)."""
        originals = [getattr(module, name)
                     for module, names in CONSULTING.items() for name in names]
        wrapped = {id(function): self.wrap(function) for function in originals}
        for module_name, module in list(sys.modules.items()):
            if module is None or not module_name.startswith("rapidmc"):
                continue
            for attribute, value in list(vars(module).items()):
                if callable(value) and id(value) in wrapped:
                    setattr(module, attribute, wrapped[id(value)])


PROBE = EngineProbe()
PROBE.install()
_consulted_on_import: dict[str, list[str]] = {}


def pytest_configure(config):
    config.addinivalue_line(
        "markers", f"{MARK}: the module's outcome cannot depend on the search engine; "
                   "the Python-engine run of .ci/run leaves it out (tests/conftest.py)")


@pytest.hookimpl(hookwrapper=True)
def pytest_make_collect_report(collector):
    if not isinstance(collector, pytest.Module):
        yield
        return
    PROBE.start()
    yield
    called = PROBE.take()
    if called:
        _consulted_on_import[collector.nodeid] = called


# each phase of a test (setup, call, teardown) starts the probe afresh; its report takes it
@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_setup(item):
    PROBE.start()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item):
    PROBE.start()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_teardown(item):
    PROBE.start()
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    called = PROBE.take()
    if call.when == "setup":
        module = item.getparent(pytest.Module)
        called = sorted(set(called) | set(_consulted_on_import.get(
            module.nodeid if module is not None else "", [])))
    if called and item.get_closest_marker(MARK) is not None and report.passed:
        report.outcome = "failed"
        report.longrepr = (
            f"{item.nodeid} is marked {MARK} but consults the search engine "
            f"({', '.join(called)}) during {call.when}: its outcome can "
            f"depend on the engine, so it must run in the Python-engine run too; remove the "
            f"mark from its module (tests/conftest.py)")
