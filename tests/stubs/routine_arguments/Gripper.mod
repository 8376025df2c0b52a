MODULE Gripper
  ! Issue 28: arguments of routines of a module not given. Missing data passed only where
  ! nothing tells the parameter's type (nForce) takes the num assumed for the parameter
  ! instead of being left undeclared; one call's typed argument types the other calls'
  ! missing arguments (sGripMode from "soft"); an aggregate argument makes an array of its
  ! parts' type (num{*}, not num) or, with parts of several types, a record shaped by it.
  PROC main()
    GripForce nForce, 3;
    GripMode "soft";
    GripMode sGripMode;
    MoveOffset [10, 20, 30];
    LogPart ["box", 2, TRUE];
  ENDPROC
ENDMODULE
