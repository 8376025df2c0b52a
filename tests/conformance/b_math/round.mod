MODULE MainModule
  ! Tests: Round to Dec decimals (manual example 0.38521) and to an integer without Dec,
  ! for positive and negative values (no ties: tie-breaking is undocumented).
  PROC main()
    TPWrite "dec3=" \Num:=Round(0.38521 \Dec:=3);
    TPWrite "dec1=" \Num:=Round(0.38521 \Dec:=1);
    TPWrite "dec0=" \Num:=Round(0.38521);
    TPWrite "up=" \Num:=Round(3.7);
    TPWrite "neg=" \Num:=Round(-3.7);
    TPWrite "dec2=" \Num:=Round(1234.5678 \Dec:=2);
  ENDPROC
ENDMODULE
