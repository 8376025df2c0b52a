MODULE MainModule
  ! Tests: TPWrite \Bool appends TRUE or FALSE, also for a computed condition.
  PROC main()
    VAR bool ready := TRUE;
    TPWrite "ready=" \Bool:=ready;
    TPWrite "not ready=" \Bool:=NOT ready;
    TPWrite "cmp=" \Bool:=3 > 4;
  ENDPROC
ENDMODULE
