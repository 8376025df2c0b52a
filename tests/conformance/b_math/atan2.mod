MODULE MainModule
  ! Tests: ATan2(Y, X) takes Y first and resolves the quadrant; result in [-180, 180] degrees.
  PROC main()
    TPWrite "q1=" \Num:=Round(ATan2(1, 1) \Dec:=3);
    TPWrite "q2=" \Num:=Round(ATan2(1, -1) \Dec:=3);
    TPWrite "q3=" \Num:=Round(ATan2(-1, -1) \Dec:=3);
    TPWrite "q4=" \Num:=Round(ATan2(-1, 1) \Dec:=3);
    TPWrite "yaxis=" \Num:=Round(ATan2(1, 0) \Dec:=3);
    TPWrite "xaxis=" \Num:=ATan2(0, 1);
  ENDPROC
ENDMODULE
