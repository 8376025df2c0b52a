MODULE MainModule
  ! Tests: Cos takes its angle in degrees.
  PROC main()
    TPWrite "cos0=" \Num:=Cos(0);
    TPWrite "cos60=" \Num:=Round(Cos(60) \Dec:=4);
    TPWrite "cos180=" \Num:=Round(Cos(180) \Dec:=4);
    TPWrite "cos120=" \Num:=Round(Cos(120) \Dec:=4);
  ENDPROC
ENDMODULE
