MODULE MainModule
  ! Tests: ByteToStr pads \Hex to 2, \Okt to 3 and \Bin to 8 digits (documented ranges
  ! "00".."FF", "000".."377", "00000000".."11111111"); decimal is not padded.
  PROC main()
    VAR byte data1 := 5;
    TPWrite "dec=" + ByteToStr(data1);
    TPWrite "hex=" + ByteToStr(data1 \Hex);
    TPWrite "okt=" + ByteToStr(data1 \Okt);
    TPWrite "bin=" + ByteToStr(data1 \Bin);
  ENDPROC
ENDMODULE
