MODULE MainModule
  ! Tests: ByteToStr converts a byte to decimal (default), \Hex, \Okt, \Bin and \Char text
  ! (manual example 122 = "7A" = "172" = "01111010" = "z").
  PROC main()
    VAR byte data1 := 122;
    TPWrite "dec=" + ByteToStr(data1);
    TPWrite "hex=" + ByteToStr(data1 \Hex);
    TPWrite "okt=" + ByteToStr(data1 \Okt);
    TPWrite "bin=" + ByteToStr(data1 \Bin);
    TPWrite "char=" + ByteToStr(data1 \Char);
  ENDPROC
ENDMODULE
