MODULE MainModule
  ! Tests: Trunc cuts toward zero to Dec decimals (manual example 0.38521) or to an integer.
  PROC main()
    TPWrite "dec3=" \Num:=Trunc(0.38521 \Dec:=3);
    TPWrite "dec1=" \Num:=Trunc(0.38521 \Dec:=1);
    TPWrite "dec0=" \Num:=Trunc(0.38521);
    TPWrite "neg=" \Num:=Trunc(-2.7);
    TPWrite "pos=" \Num:=Trunc(2.7);
    TPWrite "frac=" \Num:=Trunc(9.99 \Dec:=1);
  ENDPROC
ENDMODULE
