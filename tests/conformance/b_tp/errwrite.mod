MODULE MainModule
  ! Tests: ErrWrite logs an event-log message (not FlexPendant output) and execution continues,
  ! with \W, \I and the optional reason lines.
  ! ASSUMPTION: event-log messages do not appear on stdout.
  PROC main()
    TPWrite "before";
    ErrWrite "Gripper", "Part lost";
    ErrWrite \W, "Gripper", "Low pressure" \RL2:="Check the air supply";
    ErrWrite \I, "Cell", "Cycle started" \RL2:="line 2" \RL3:="line 3" \RL4:="line 4";
    TPWrite "after";
  ENDPROC
ENDMODULE
