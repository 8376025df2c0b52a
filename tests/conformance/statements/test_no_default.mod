MODULE test_no_default
  ! Tests: a TEST without DEFAULT whose value matches no CASE does nothing
  ! and execution continues after ENDTEST.
  PROC main()
    VAR num v := 7;
    TEST v
    CASE 1:
      TPWrite "one";
    CASE 2:
      TPWrite "two";
    ENDTEST
    TPWrite "after";
  ENDPROC
ENDMODULE
