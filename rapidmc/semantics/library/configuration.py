"""The controller's configuration database as ReadCfgData reads it (issue 19).

ReadCfgData names an instance by ``/DOMAIN/TYPE/INSTANCE`` (MOC, SYS, EIO,
SIO, PROC; the leading slash may be left out) and one of its attributes.
What rapidmc knows about an instance comes from two places:

* a loaded backup's SYSPAR files (``load.configuration`` reads them into a
  ``Configuration``): for a domain whose file the backup has, that file is the
  truth. An instance it lists is found, with the attribute's value when the file
  writes one; an attribute the file leaves out has its default, which rapidmc
  does not know. An instance it does not list is not found (ERR_CFG_NOTFND).
* otherwise the instances every standard six-axis single-robot controller has
  (``STANDARD``, from public backups' MOC.cfg and SYS.cfg and from ABB's own
  calibration-position program): found, with a value rapidmc does not know.

Anything else is not known either way: when checking, the read is found (the
data keeps its value) or raises ERR_CFG_NOTFND, a choice made at the run's first
read of that instance and attribute and kept for the later ones
(``configuration_outcomes``).  A value
rapidmc does not know is never invented: the data keeps its value, and the
RMC702 note beside the verdicts says that the check assumes it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

# Outcomes of a look-up.
FOUND, NOT_FOUND, NOT_KNOWN = "found", "not found", "not known"
UNKNOWN_VALUE = object()          # found, but its value is the controller's

_ROBOT_JOINTS = tuple(f"rob1_{axis}" for axis in range(1, 7))
_ARM_ATTRIBUTES = ("use_arm_type", "use_acc_data", "use_arm_calib", "use_check_point",
                   "use_customer_arm_load", "upper_joint_bound", "lower_joint_bound",
                   "upper_joint_bound_max", "lower_joint_bound_min", "cal_position",
                   "independent_joint_on")
_MOTOR_CALIB_ATTRIBUTES = ("com_offset", "valid_com_offset", "cal_offset", "valid_cal_offset",
                           "fine_cal_position")
_ROBOT_ATTRIBUTES = ("use_robot_serial_number", "use_robot_type", "use_robot_calib",
                     *(f"use_joint_{n}" for n in range(6)), "use_lin_jog", "use_reorient_jog",
                     "use_joint_jog")

# (domain, type) -> (instance names, attribute names) of a standard single six-axis robot.
STANDARD = {
    ("MOC", "ROBOT"): (("ROB_1",), _ROBOT_ATTRIBUTES),
    ("MOC", "ROBOT_SERIAL_NUMBER"): (("rob_1",), ()),
    ("MOC", "ARM"): (_ROBOT_JOINTS, _ARM_ATTRIBUTES),
    ("MOC", "ARM_CALIB"): (_ROBOT_JOINTS, ()),
    ("MOC", "JOINT_CALIB"): (_ROBOT_JOINTS, ()),
    ("MOC", "MOTOR_CALIB"): (_ROBOT_JOINTS, _MOTOR_CALIB_ATTRIBUTES),
    ("MOC", "MOTION_SYSTEM"): (("system_1",), ("min_temp_ambient_cabinet",
                                               "max_temp_ambient_cabinet",
                                               "min_temp_ambient_robot",
                                               "max_temp_ambient_robot")),
    ("MOC", "MOTION_PLANNER"): (("motion_planner_1",), ()),
    ("SYS", "CAB_TASKS"): (("T_ROB1",), ("type", "motiontask")),
    ("SYS", "SYS_MISC"): (("NoOfRetry",), ("value",)),
}
STANDARD_TEXT = ("the controller's configuration (a backup's SYSPAR files when loaded, else "
                 "the instances of a standard six-axis single robot, found with values "
                 "rapidmc does not know; any other instance found or not, the same at every "
                 "read of a run)")


@dataclass
class Configuration:
    """The instances of a backup's SYSPAR files: domain -> type -> instances (attributes)."""

    # DOMAIN -> TYPE (upper case) -> list of instances; an instance maps attribute names
    # (lower case) to their text, True for a flag written without a value
    domains: dict = field(default_factory=dict)

    def instances(self, domain: str, type_name: str) -> list:
        return self.domains.get(domain.upper(), {}).get(type_name.upper(), [])


@dataclass(frozen=True)
class Lookup:
    """What a read finds: ``outcome`` (FOUND, NOT_FOUND, NOT_KNOWN) and, when found, the
    attribute's text (``UNKNOWN_VALUE`` when rapidmc does not know it)."""

    outcome: str
    value: object = UNKNOWN_VALUE


def split_path(path: str) -> Optional[tuple[str, str, str]]:
    """``"/MOC/ARM/rob1_1"`` -> ("MOC", "ARM", "rob1_1"); None for another form (the
    \\ListNo form ``/DOMAIN/TYPE/ATTRIBUTE/VALUE`` among them)."""
    parts = path.strip().strip("/").split("/")
    if len(parts) != 3 or not all(parts):
        return None
    return parts[0].upper(), parts[1].upper(), parts[2]


def look_up(configuration: Optional[Configuration], path: str, attribute: str) -> Lookup:
    """Whether ``path`` and ``attribute`` exist, and their value, as far as rapidmc knows."""
    parts = split_path(path)
    if parts is None:
        return Lookup(NOT_KNOWN)
    domain, type_name, instance = parts
    attribute = attribute.strip().lower()
    if configuration is not None and domain in configuration.domains:
        return _in_file(configuration.instances(domain, type_name), instance, attribute)
    return _standard(domain, type_name, instance, attribute)


def _in_file(instances: list, instance: str, attribute: str) -> Lookup:
    exact = [i for i in instances if i.get("name") == instance]
    if not exact:
        folded = [i for i in instances if str(i.get("name", "")).lower() == instance.lower()]
        # a name that differs only in case: whether the controller matches it is not known
        return Lookup(NOT_KNOWN if folded else NOT_FOUND)
    attributes = exact[0]
    if attribute in attributes:
        return Lookup(FOUND, attributes[attribute])
    if any(attribute in other for other in instances):
        return Lookup(FOUND)          # the type has it; this instance keeps the default
    return Lookup(NOT_KNOWN)


def _standard(domain: str, type_name: str, instance: str, attribute: str) -> Lookup:
    names, attributes = STANDARD.get((domain, type_name), ((), ()))
    if instance not in names:
        return Lookup(NOT_KNOWN)
    if attribute == "name":
        return Lookup(FOUND, instance)
    return Lookup(FOUND) if attribute in attributes else Lookup(NOT_KNOWN)
