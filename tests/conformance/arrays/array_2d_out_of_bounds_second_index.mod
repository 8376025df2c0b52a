MODULE array_2d_second_index_oob
  ! Tests: each index of a multi-dimensional array is checked against its own
  ! dimension: m{1,4} on a {3,3} array raises ERR_OUTOFBND.
  VAR num m{3, 3};
  PROC main()
    m{3, 3} := 1;
    TPWrite "ok";
    m{1, 4} := 1;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
