MODULE MainModule
  ! Tests: ATan returns degrees in [-90, 90].
  PROC main()
    TPWrite "atan1=" \Num:=Round(ATan(1) \Dec:=3);
    TPWrite "atanm1=" \Num:=Round(ATan(-1) \Dec:=3);
    TPWrite "atan0=" \Num:=ATan(0);
    TPWrite "atanbig=" \Num:=Round(ATan(1000000) \Dec:=1);
  ENDPROC
ENDMODULE
