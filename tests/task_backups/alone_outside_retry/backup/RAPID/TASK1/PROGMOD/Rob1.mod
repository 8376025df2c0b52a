MODULE Rob1
  ! Written for the test (issue 28): robot 2 (not loaded) sets nParts; robot 1 divides by a
  ! count its handler never repairs and retries: ERR_EXCRTYMAX, a true defect.
  PERS num nParts := 0;
  VAR num share := 0;
  VAR num divisor := 0;

  PROC main()
    WaitUntil nParts > 0;
    share := nParts / divisor;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
