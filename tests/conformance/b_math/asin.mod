MODULE MainModule
  ! Tests: ASin returns degrees in [-90, 90].
  PROC main()
    TPWrite "asin0.5=" \Num:=Round(ASin(0.5) \Dec:=3);
    TPWrite "asin1=" \Num:=Round(ASin(1) \Dec:=3);
    TPWrite "asinm1=" \Num:=Round(ASin(-1) \Dec:=3);
  ENDPROC
ENDMODULE
