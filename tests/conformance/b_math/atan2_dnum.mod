MODULE MainModule
  ! Tests: ATan2Dnum(Y, X) takes Y first and resolves the quadrant in double precision.
  PROC main()
    VAR dnum y := 1;
    VAR dnum x := -1;
    VAR dnum zero := 0;
    TPWrite "q2=" \Dnum:=RoundDnum(ATan2Dnum(y, x) \Dec:=9);
    TPWrite "yaxis=" \Dnum:=RoundDnum(ATan2Dnum(y, zero) \Dec:=9);
  ENDPROC
ENDMODULE
