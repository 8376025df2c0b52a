MODULE Prog
  ! A RAISE in a routine whose ERROR handler has no TRYNEXT never goes on with the
  ! statement after it: the handler's end leaves the routine.  In Retried, whose
  ! handler does TRYNEXT, the statement after the RAISE runs.
  VAR num answer := 0;
  VAR num trips := 0;
  PROC Refuse()
    RAISE ERR_DIVZERO;
    trips := trips + 1;
  ERROR
    trips := -1;
  ENDPROC
  PROC Retried()
    RAISE ERR_DIVZERO;
    trips := trips + 2;
  ERROR
    TRYNEXT;
  ENDPROC
  PROC main()
    TPReadNum answer, "go?";
    IF answer = 7 THEN
      Refuse;
      Retried;
    ENDIF
  ENDPROC
ENDMODULE
