MODULE MainModule
  ! Tests: EulerZYX recovers the \Z, \Y and \X angles of an orientation built by OrientZYX.
  PROC main()
    VAR orient o;
    o := OrientZYX(30, 20, 10);
    TPWrite "z=" \Num:=Round(EulerZYX(\Z, o) \Dec:=2);
    TPWrite "y=" \Num:=Round(EulerZYX(\Y, o) \Dec:=2);
    TPWrite "x=" \Num:=Round(EulerZYX(\X, o) \Dec:=2);
    TPWrite "z of identity=" \Num:=EulerZYX(\Z, [1, 0, 0, 0]);
  ENDPROC
ENDMODULE
