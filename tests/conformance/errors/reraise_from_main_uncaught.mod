MODULE reraise_from_main_uncaught
  ! Tests: RAISE in the ERROR handler of main (the top of the call chain)
  ! leaves the error uncaught: the program stops with exit code 1.
  PROC main()
    VAR num z := 0;
    z := 5 / z;
  ERROR
    TPWrite "main handler";
    RAISE;
  ENDPROC
ENDMODULE
