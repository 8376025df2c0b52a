MODULE MainModule
  ! Tests: Distance is the Euclidean distance between two points, symmetric, 0 for equal points.
  PROC main()
    VAR pos a := [1, 2, 3];
    VAR pos b := [4, 6, 3];
    TPWrite "ab=" \Num:=Distance(a, b);
    TPWrite "ba=" \Num:=Distance(b, a);
    TPWrite "aa=" \Num:=Distance(a, a);
    TPWrite "3d=" \Num:=Distance([0, 0, 0], [2, 3, 6]);
  ENDPROC
ENDMODULE
