MODULE array_2d_aggregate
  ! Tests: a 2-dimensional array is initialised by a nested aggregate, row
  ! by row: m{r,c} is the c-th item of the r-th inner aggregate.
  VAR num m{2, 3} := [[1, 2, 3], [4, 5, 6]];
  PROC main()
    TPWrite "m{1,3}=" \Num:=m{1, 3};
    TPWrite "m{2,1}=" \Num:=m{2, 1};
    m{2, 2} := 50;
    TPWrite "row2=" \Num:=m{2, 1} + m{2, 2} + m{2, 3};
  ENDPROC
ENDMODULE
