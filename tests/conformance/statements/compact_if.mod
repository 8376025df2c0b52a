MODULE compact_if
  ! Tests: compact IF (no THEN/ENDIF) runs its single statement only when the
  ! condition is TRUE; works with assignments and procedure calls.
  PROC main()
    VAR num x := 5;
    IF x > 0 TPWrite "positive";
    IF x < 0 TPWrite "negative";
    IF x = 5 x := 6;
    TPWrite "x=" \Num:=x;
  ENDPROC
ENDMODULE
