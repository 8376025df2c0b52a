MODULE array_index_zero_error
  ! Tests: arrays are indexed from 1: index 0 raises ERR_OUTOFBND, which
  ! uncaught stops the program (exit 1).
  VAR num a{3} := [1, 2, 3];
  PROC main()
    VAR num i := 0;
    TPWrite "first=" \Num:=a{1};
    TPWrite "zero=" \Num:=a{i};
  ENDPROC
ENDMODULE
