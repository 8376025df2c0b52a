MODULE MainModule
  ! Tests: StrToByte parses decimal (default), \Hex, \Okt, \Bin and \Char text into a byte.
  PROC main()
    TPWrite "dec=" \Num:=StrToByte("10");
    TPWrite "hex=" \Num:=StrToByte("AE" \Hex);
    TPWrite "okt=" \Num:=StrToByte("176" \Okt);
    TPWrite "bin=" \Num:=StrToByte("00001010" \Bin);
    TPWrite "char=" \Num:=StrToByte("A" \Char);
  ENDPROC
ENDMODULE
