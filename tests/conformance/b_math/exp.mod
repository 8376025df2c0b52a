MODULE MainModule
  ! Tests: Exp computes e raised to the argument (Exp(0)=1, Exp(1)=e, Exp(-1)=1/e).
  PROC main()
    TPWrite "exp0=" \Num:=Exp(0);
    TPWrite "exp1=" \Num:=Round(Exp(1) \Dec:=4);
    TPWrite "expm1=" \Num:=Round(Exp(-1) \Dec:=4);
    TPWrite "exp2=" \Num:=Round(Exp(2) \Dec:=3);
  ENDPROC
ENDMODULE
