MODULE MainModule
  ! Tests: ASinDnum returns degrees in double precision.
  PROC main()
    VAR dnum half := 0.5;
    VAR dnum one := 1;
    TPWrite "asin0.5=" \Dnum:=RoundDnum(ASinDnum(half) \Dec:=9);
    TPWrite "asin1=" \Dnum:=RoundDnum(ASinDnum(one) \Dec:=9);
  ENDPROC
ENDMODULE
