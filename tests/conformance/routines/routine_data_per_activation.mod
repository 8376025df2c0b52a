MODULE routine_data_per_activation
  ! Tests: each activation of a recursive procedure has its own routine
  ! data: the value set before the recursive call is intact after it.
  PROC nest(num depth)
    VAR num mine;
    mine := depth * 10;
    IF depth < 3 nest depth + 1;
    TPWrite "depth " \Num:=mine;
  ENDPROC
  PROC main()
    nest 1;
  ENDPROC
ENDMODULE
