MODULE uncaught_divzero
  ! Tests: an error no handler catches stops the program: output written
  ! before stays, the rest does not run, exit code 1, the error named on
  ! stderr.
  PROC compute()
    VAR num d := 0;
    TPWrite "computing";
    d := 1 / d;
  ENDPROC
  PROC main()
    TPWrite "start";
    compute;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
