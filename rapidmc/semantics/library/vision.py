"""Integrated Vision: cameras, jobs, images and the parts found in them.

What a camera finds is the world's decision.  CamNumberOfResults answers
0, 1 or 2 parts (a nondeterministic choice when model checking, 0 in
``run``); CamGetResult gives a part (a neutral cameratarget) or, when none is
left, raises ERR_CAM_NO_MORE_DATA (both possible when model checking, the
error in ``run``).  Loading jobs, modes and images change nothing rapidmc
observes.
"""
from __future__ import annotations

from ..errors import RapidError
from ..expressions import Compiled
from ..instructions import Action
from ..types import PREDEFINED_TYPES, default_value
from .arguments import NAME_ONLY, Arguments, fixed, no_effect, not_modelled
from .environment_model import where
from .registry import CHOICE, FIXED, NO_EFFECT, NOT_MODELLED, compiled

MAX_PARTS = 2
_CAMERA = "VAR cameradev Camera"

compiled(f"CamReqImage({_CAMERA} \\num SceneId \\switch KeepTargets \\switch AwaitComplete)",
         f"CamLoadJob({_CAMERA}, string Name \\switch KeepTargets \\num MaxTime)",
         f"CamStartLoadJob({_CAMERA}, string Name \\switch KeepTargets)",
         f"CamWaitLoadJob({_CAMERA})",
         f"CamSetProgramMode({_CAMERA})",
         f"CamSetRunMode({_CAMERA})",
         f"CamFlush({_CAMERA})",
         f"CamSetExposure({_CAMERA} \\num ExposureTime \\num Brightness \\num Contrast)",
         modelled=NO_EFFECT)(no_effect)
compiled(f"string CamGetName({_CAMERA})", f"string CamGetLoadedJob({_CAMERA})",
         modelled=FIXED)(fixed(""))


@compiled(f"num CamNumberOfResults({_CAMERA} \\num SceneId)", modelled=CHOICE)
def _number_of_results(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    label = f"CamNumberOfResults at {where(call.span)}"
    counts = tuple(float(n) for n in range(MAX_PARTS + 1))

    def count(m):
        return m.choose(label, counts) if m.chooser.check_mode else 0.0
    return Compiled(count, calls.return_type(entry))


@compiled(f"CamGetResult({_CAMERA}, VAR cameratarget CamTarget \\num SceneId \\num MaxTime)",
          modelled=CHOICE)
def _get_result(calls, compiler, call, entry):
    target = Arguments(calls, compiler, call, entry).fn("CamTarget")
    label = f"CamGetResult at {where(call.span)}"
    part = default_value(PREDEFINED_TYPES["CAMERATARGET"])

    def get(m):
        if not (m.chooser.check_mode and m.choose(label, (True, False))):
            raise RapidError("ERR_CAM_NO_MORE_DATA", "no (more) parts found in the image")
        m.write_ref(target(m), part)
    return Action(call.span, get)


# --- reference coverage (issue 8, item 1): named camera parameters ------------------------
# Evidence: the parameter lists of the public re-implementation jasky1640/Tenon-IDE
# (tenon/module/base.t): the camera, the parameter's name, and one optional value of type num,
# bool or string (written as one alternative group here). Setting a parameter changes nothing
# rapidmc observes; reading one would need the camera's configuration, so it stops the run.
compiled(f"CamSetParameter({_CAMERA}, string ParName \\num NumVal | bool BoolVal | string StrVal)",
         modelled=NO_EFFECT)(no_effect)
compiled(f"CamGetParameter({_CAMERA}, string ParName \\VAR num NumVar | VAR bool BoolVar "
         "| VAR string StrVar)",
         modelled=NOT_MODELLED)(not_modelled("reads a parameter of the camera's configuration, "
                                             "which rapidmc does not model"))
# From the name list only: AliasCamera. CamGetExposure stays out: the reference lists it as a
# function, whose result type nothing we found gives (that base module declares a procedure).
compiled("AliasCamera(...)", modelled=NOT_MODELLED)(NAME_ONLY)
