MODULE test_strings
  ! Tests: TEST works on strings (and any value type compared with =); the
  ! test expression is an arbitrary expression.
  PROC main()
    VAR string cmd := "st";
    TEST cmd + "op"
    CASE "go":
      TPWrite "going";
    CASE "stop", "halt":
      TPWrite "stopping";
    DEFAULT:
      TPWrite "unknown";
    ENDTEST
  ENDPROC
ENDMODULE
