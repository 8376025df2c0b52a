MODULE MainModule
  ! Tests: Stop halts the program; in a run nothing after it executes and the exit code is 0.
  PROC main()
    TPWrite "before Stop";
    Stop;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
