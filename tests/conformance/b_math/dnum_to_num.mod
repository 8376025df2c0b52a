MODULE MainModule
  ! Tests: DnumToNum narrows to num; a value that float32 cannot hold exactly is rounded
  ! (16777217 becomes 16777216).
  PROC main()
    VAR dnum small := 42.5;
    VAR dnum big := 16777217;
    TPWrite "small=" \Num:=DnumToNum(small);
    TPWrite "rounded=" \Bool:=DnumToNum(big) = 16777216;
  ENDPROC
ENDMODULE
