MODULE MainModule
  ! Tests: an uncaught ERR_INT_NOTVAL from TryInt stops the program with exit code 1.
  PROC main()
    VAR num n := 1.5;
    TPWrite "before";
    TryInt n;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
