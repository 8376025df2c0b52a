"""The progress line: format, throttling, silence off a terminal, cleanup."""
from __future__ import annotations

import io

from rapidmc.check import Progress, check_property
from rapidmc.check.progress import progress_line
from test_engine_models import NOT_INFINITELY_OFTEN_P, Counter


class Terminal(io.StringIO):
    def isatty(self):
        return True


class FakeClock:
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def test_line_format_uses_thousands_separators():
    assert progress_line(123_456, 456_789, 1_234, 2.0) == (
        "states 123,456  transitions 456,789  depth 1,234  61,728 states/s")


def test_silent_during_the_first_second_then_throttled():
    stream, clock = Terminal(), FakeClock()
    progress = Progress(stream, clock=clock)
    clock.now += 0.9
    progress.update(10, 20, 3)
    assert stream.getvalue() == ""
    clock.now += 0.2
    progress.update(1_100, 2_000, 3)
    assert stream.getvalue() == "\rstates 1,100  transitions 2,000  depth 3  1,000 states/s"
    clock.now += 0.1
    progress.update(1_200, 2_100, 3)
    assert stream.getvalue().count("\r") == 1
    clock.now += 0.5
    progress.update(1_300, 2_200, 4)
    assert stream.getvalue().count("\r") == 2


def test_finish_erases_the_line():
    stream, clock = Terminal(), FakeClock()
    progress = Progress(stream, clock=clock)
    clock.now += 2
    progress.update(5, 5, 5)
    width = len(stream.getvalue()) - 1
    progress.finish()
    assert stream.getvalue().endswith("\r" + " " * width + "\r")


def test_silent_off_a_terminal_or_when_quiet():
    for stream, quiet in ((io.StringIO(), False), (Terminal(), True)):
        clock = FakeClock()
        progress = Progress(stream, quiet=quiet, clock=clock)
        clock.now += 5
        progress.update(1, 1, 1)
        progress.finish()
        assert stream.getvalue() == ""


def test_the_engine_reports_progress_and_clears_it():
    stream = Terminal()
    progress = Progress(stream, delay=0, interval=0)
    result = check_property(Counter(10_000), NOT_INFINITELY_OFTEN_P, lambda x: int(x == 0),
                            progress=progress)
    assert result.verdict == "HOLDS"
    text = stream.getvalue()
    assert text.count("\rstates ") >= 5
    assert text.endswith("\r")
    assert progress.width == 0
