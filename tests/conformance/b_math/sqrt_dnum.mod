MODULE MainModule
  ! Tests: SqrtDnum computes in double precision (sqrt of 2^32 is exactly 65536).
  PROC main()
    VAR dnum big := 4294967296;
    VAR dnum small := 2.25;
    TPWrite "big=" \Dnum:=SqrtDnum(big);
    TPWrite "small=" \Dnum:=SqrtDnum(small);
  ENDPROC
ENDMODULE
