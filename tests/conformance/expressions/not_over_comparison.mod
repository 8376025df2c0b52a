MODULE not_over_comparison
  ! Tests: NOT x = 3 means NOT (x = 3): comparisons are evaluated first.
  PROC main()
    VAR num x := 3;
    TPWrite "NOT x=3: " \Bool:=NOT x = 3;
    TPWrite "NOT x=4: " \Bool:=NOT x = 4;
  ENDPROC
ENDMODULE
