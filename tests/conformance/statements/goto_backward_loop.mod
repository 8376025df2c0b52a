MODULE goto_backward_loop
  ! Tests: GOTO to an earlier label repeats statements (a loop built from a
  ! label and a compact IF with GOTO).
  PROC main()
    VAR num n := 0;
  again:
    n := n + 1;
    TPWrite "n=" \Num:=n;
    IF n < 3 GOTO again;
    TPWrite "done";
  ENDPROC
ENDMODULE
