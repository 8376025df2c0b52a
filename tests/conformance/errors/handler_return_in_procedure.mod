MODULE handler_return_in_procedure
  ! Tests: RETURN in a procedure's ERROR handler ends the procedure; its
  ! remaining statements do not run and the caller continues after the call.
  PROC work()
    VAR num z := 0;
    TPWrite "work starts";
    z := 1 / z;
    TPWrite "work not finished";
  ERROR
    TPWrite "work handler";
    RETURN;
  ENDPROC
  PROC main()
    work;
    TPWrite "main continues";
  ENDPROC
ENDMODULE
