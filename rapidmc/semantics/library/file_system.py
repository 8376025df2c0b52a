"""The controller's file system: directories, file sizes, copying and removing files.

rapidmc does not model the controller's disks.  Whether a file exists is the
world's decision (IsFile: TRUE or FALSE, a nondeterministic choice when model
checking, FALSE in ``run``); directories read as empty and sizes as 0;
creating, copying, renaming and removing change nothing rapidmc observes.
WriteAnyBin changes nothing; ReadAnyBin, which would read data of any type in
binary form, stops the run (RMC305).
"""
from __future__ import annotations

from ..expressions import Compiled
from .arguments import Arguments, fixed, no_effect, not_modelled
from .environment_model import where
from .registry import CHOICE, FIXED, NO_EFFECT, NOT_MODELLED, compiled

compiled("MakeDir(string Path)",
         "RemoveDir(string Path)",
         "RemoveFile(string Path)",
         "RenameFile(string OldPath, string NewPath)",
         "CopyFile(string OldPath, string NewPath)",
         "OpenDir(VAR dir Dev, string Path)",
         "CloseDir(VAR dir Dev)",
         "WriteAnyBin(VAR iodev IODevice, anytype Data)",
         modelled=NO_EFFECT)(no_effect)
compiled("ReadAnyBin(VAR iodev IODevice, VAR anytype Data \\num Time)",
         modelled=NOT_MODELLED)(not_modelled("reads data of any type in binary form, which "
                                             "rapidmc does not model"))
compiled("bool ReadDir(VAR dir Dev, VAR string FileName)", modelled=FIXED)(fixed(False))
compiled("num FileSize(string Path)",
         "num FSSize(string Name \\switch Total | switch Free \\switch Kbyte \\switch Mbyte)",
         "num FileTime(string Path \\switch ModifyTime | switch AccessTime | switch StatCTime "
             "\\VAR stringdig StrDig)",
         modelled=FIXED)(fixed(0.0))


@compiled("bool IsFile(string Path \\switch Directory | switch Fifo | switch RegFile "
              "| switch BlockSpec | switch CharSpec)",
          modelled=CHOICE)
def _is_file(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    label = f"IsFile at {where(call.span)}"

    def exists(m):
        return m.choose(label, (False, True)) if m.chooser.check_mode else False
    return Compiled(exists, calls.return_type(entry))


# --- reference coverage (issue 8, item 1): times of files and loaded modules ------------------
compiled("dnum FileTimeDnum(string Path \\switch ModifyTime | switch AccessTime "
             "| switch StatCTime)",
         "num ModTime(string Object \\VAR stringdig StrDig)",
         "dnum ModTimeDnum(string Object)",
         modelled=FIXED)(fixed(0.0))
