MODULE MainModule
  ! Tests: DotProd is x1*x2 + y1*y2 + z1*z2.
  PROC main()
    TPWrite "dot=" \Num:=DotProd([1, 2, 3], [4, 5, 6]);
    TPWrite "orth=" \Num:=DotProd([1, 0, 0], [0, 1, 0]);
    TPWrite "neg=" \Num:=DotProd([-1, 2, 0], [3, 1, 7]);
  ENDPROC
ENDMODULE
