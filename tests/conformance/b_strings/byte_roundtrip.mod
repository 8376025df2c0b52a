MODULE MainModule
  ! Tests: StrToByte inverts ByteToStr for every byte value in each representation.
  PROC main()
    VAR num bad := 0;
    FOR i FROM 0 TO 255 DO
      IF StrToByte(ByteToStr(i)) <> i Incr bad;
      IF StrToByte(ByteToStr(i \Hex) \Hex) <> i Incr bad;
      IF StrToByte(ByteToStr(i \Okt) \Okt) <> i Incr bad;
      IF StrToByte(ByteToStr(i \Bin) \Bin) <> i Incr bad;
    ENDFOR
    TPWrite "mismatches=" \Num:=bad;
  ENDPROC
ENDMODULE
