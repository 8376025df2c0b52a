MODULE array_3d
  ! Tests: 3-dimensional arrays: nested aggregates three deep, indexing with
  ! three indices, and Dim of each dimension.
  CONST num c{2, 2, 3} := [[[1, 2, 3], [4, 5, 6]], [[7, 8, 9], [10, 11, 12]]];
  PROC main()
    TPWrite "c{2,1,2}=" \Num:=c{2, 1, 2};
    TPWrite "c{1,2,3}=" \Num:=c{1, 2, 3};
    TPWrite "dims=" \Num:=Dim(c, 1) * 100 + Dim(c, 2) * 10 + Dim(c, 3);
  ENDPROC
ENDMODULE
