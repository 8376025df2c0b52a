MODULE MainModule
  ! Tests: RETURN in main ends the program normally (exit code 0).
  PROC main()
    TPWrite "start";
    RETURN;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
