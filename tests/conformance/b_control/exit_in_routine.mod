MODULE MainModule
  ! Tests: EXIT in a called routine terminates the whole program (normal end, exit code 0);
  ! nothing after it runs, in the routine or in the caller.
  PROC main()
    TPWrite "start";
    Sub;
    TPWrite "not reached in main";
  ENDPROC

  PROC Sub()
    TPWrite "in Sub";
    EXIT;
    TPWrite "not reached in Sub";
  ENDPROC
ENDMODULE
