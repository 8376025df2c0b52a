MODULE CellIO
  ! Tests: errors of a second module come after the first module's, in line order.
  PROC GripClose()
    SetDO doGrip, 1;
    WaitTime tGripDelay;
    Abs 3;
  ENDPROC
ENDMODULE
