MODULE test_errnum_constants
  ! Tests: TEST on a bool expression with CASE TRUE / CASE FALSE, and TEST
  ! on an alias type (errnum) with CONST case values.
  CONST errnum E_LOW := 1;
  CONST errnum E_HIGH := 2;
  PROC main()
    VAR errnum code := 2;
    TEST code > 1
    CASE TRUE:
      TPWrite "above one";
    CASE FALSE:
      TPWrite "not above one";
    ENDTEST
    TEST code
    CASE E_LOW:
      TPWrite "low";
    CASE E_HIGH:
      TPWrite "high";
    ENDTEST
  ENDPROC
ENDMODULE
