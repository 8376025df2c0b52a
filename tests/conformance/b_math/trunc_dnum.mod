MODULE MainModule
  ! Tests: TruncDnum cuts toward zero in double precision.
  PROC main()
    VAR dnum e := 2.718281828459;
    VAR dnum big := 4294967295.9;
    TPWrite "dec5=" \Dnum:=TruncDnum(e \Dec:=5);
    TPWrite "neg=" \Dnum:=TruncDnum(-e);
    TPWrite "big=" \Dnum:=TruncDnum(big);
  ENDPROC
ENDMODULE
