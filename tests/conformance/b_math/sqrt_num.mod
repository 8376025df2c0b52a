MODULE MainModule
  ! Tests: Sqrt of perfect squares, of zero, and of 2 (rounded to 4 decimals).
  PROC main()
    TPWrite "sqrt16=" \Num:=Sqrt(16);
    TPWrite "sqrt2.25=" \Num:=Sqrt(2.25);
    TPWrite "sqrt0=" \Num:=Sqrt(0);
    TPWrite "sqrt2=" \Num:=Round(Sqrt(2) \Dec:=4);
  ENDPROC
ENDMODULE
