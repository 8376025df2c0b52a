MODULE CellMain
  ! LoadIdentify, RobotWare's load identification service routine, called without
  ! arguments from a routine of the program's own (as a public controller backup does).
  ! Started from the service routine, the check stops where it is reached: rapidmc does
  ! not model the operator dialogue and the moves that identify the load.
  PERS tooldata tGripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  VAR num nCycles := 0;

  PROC main()
    nCycles := nCycles + 1;
    IF nCycles > 3 nCycles := 0;
  ENDPROC

  ! A service routine: the operator starts it by hand after changing the gripper.
  PROC rIdentifyGripper()
    MoveAbsJ [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v200, fine, tGripper;
    LoadIdentify;
  ENDPROC
ENDMODULE
