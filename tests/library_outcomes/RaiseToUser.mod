MODULE UserLevel
  ! Tests: RaiseToUser, known by name only, loads with its switches and stops the run where
  ! a NOSTEPIN routine's error handler reaches it (RMC305), after the output before it.
  VAR num nDivisor := 0;
  PROC main()
    TPWrite "start";
    Divide;
    TPWrite "never reached";
  ERROR
    TPWrite "user level handler";
  ENDPROC
ENDMODULE

MODULE Library (SYSMODULE, NOSTEPIN)
  PROC Divide()
    VAR num quotient;
    quotient := 10 / nDivisor;
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      TPWrite "library handler";
      RaiseToUser \Continue \ErrorNumber:=ERR_DIVZERO;
    ENDIF
  ENDPROC
ENDMODULE
