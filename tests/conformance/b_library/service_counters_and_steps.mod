MODULE MainModule
  ! Tests: the axis distance and move time counters read 0 (rapidmc moves by jumps) and
  ! their resets, StepBwdPath, IOBusStart and CancelLoad change nothing; SystemStopAction
  ! \Stop stops the program like Stop, so the last line is never written.
  VAR loadsession session;
  PROC main()
    TPWrite "distance " \Num:=GetAxisDistance(ROB_1, 1);
    TPWrite "move time " \Num:=GetAxisMoveTime(ROB_1, 6);
    ResetAxisDistance ROB_1, 1;
    ResetAxisMoveTime ROB_1, 6;
    StepBwdPath 30, 1;
    IOBusStart "Local";
    CancelLoad session;
    TPWrite "stopping";
    SystemStopAction \Stop;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
