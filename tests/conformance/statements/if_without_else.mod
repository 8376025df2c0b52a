MODULE if_without_else
  ! Tests: an IF without ELSE whose condition is FALSE executes nothing and
  ! continues after ENDIF.
  PROC main()
    VAR num x := 0;
    IF x > 0 THEN
      TPWrite "positive";
    ENDIF
    TPWrite "after";
  ENDPROC
ENDMODULE
