MODULE MainModule
  ! Tests: OrientZYX(Z, Y, X) builds the quaternion [q1 scalar, q2, q3, q4] of the Euler ZYX
  ! rotation: 90 degrees about z and about x (third argument).
  PROC main()
    VAR orient o;
    o := OrientZYX(90, 0, 0);
    TPWrite "z q1=" \Num:=Round(o.q1 \Dec:=4);
    TPWrite "z q4=" \Num:=Round(o.q4 \Dec:=4);
    TPWrite "z q2,q3 zero=" \Bool:=Abs(o.q2) < 0.0001 AND Abs(o.q3) < 0.0001;
    o := OrientZYX(0, 0, 90);
    TPWrite "x q1=" \Num:=Round(o.q1 \Dec:=4);
    TPWrite "x q2=" \Num:=Round(o.q2 \Dec:=4);
    TPWrite "x q3,q4 zero=" \Bool:=Abs(o.q3) < 0.0001 AND Abs(o.q4) < 0.0001;
    o := OrientZYX(0, 0, 0);
    TPWrite "identity=" \Bool:=Abs(o.q1 - 1) < 0.0001 AND Abs(o.q2) + Abs(o.q3) + Abs(o.q4) < 0.0001;
  ENDPROC
ENDMODULE
