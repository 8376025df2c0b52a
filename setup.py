"""The optional compiled search core: ``rapidmc/check/_native.c`` built by the install.

Everything else is in pyproject.toml.  The extension is optional, as pyrsistent's C
extension is: when it cannot be compiled (no C compiler, no Python headers) the install
goes on without it, with a warning, and rapidmc searches with its pure Python engine
(``rapidmc.check.native`` says which engine runs; ``rapidmc --version`` shows it).
Set ``RAPIDMC_NO_NATIVE=1`` to install without building it.
"""
import os
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class OptionalBuildExt(build_ext):
    """``build_ext`` whose failure is a warning: the package works without the extension."""

    def run(self):
        try:
            super().run()
        except Exception as exc:  # no compiler at all (setuptools raises various errors)
            self._skipped(exc)

    def build_extension(self, ext):
        try:
            super().build_extension(ext)
        except Exception as exc:
            self._skipped(exc)

    @staticmethod
    def _skipped(exc):
        print(f"warning: rapidmc's native search core was not built ({exc}); "
              "the pure Python engine will be used", file=sys.stderr)


NATIVE = [] if os.environ.get("RAPIDMC_NO_NATIVE") else [
    Extension("rapidmc.check._native", ["rapidmc/check/_native.c", "rapidmc/check/_packed.c",
                                        "rapidmc/check/_nodes.c"],
              depends=["rapidmc/check/_common.h"],
              extra_compile_args=["-O2", "-std=c99"] if os.name != "nt" else []),
]

setup(ext_modules=NATIVE, cmdclass={"build_ext": OptionalBuildExt})
