MODULE BinaryLog
  ! Our own program in the style of a robot-side file decoder (survey round 8): a
  ! binary file written with \Write\Bin, read back with \Read\Bin and ReadRawBytes
  ! without \NoOfBytes, and a text file read line by line until ReadStr gives EOF.
  VAR iodev logFile;
  VAR iodev textFile;
  VAR rawbytes rawOut;
  VAR rawbytes rawIn;
  VAR string line;
  VAR num nBytesRead := -1;
  VAR bool bAtEnd := FALSE;
  VAR bool bGotLine := FALSE;

  PROC main()
    ClearRawBytes rawOut;
    PackRawBytes 7, rawOut, 1 \IntX:=UINT;
    Open "HOME:" \File:="cycle.bin", logFile \Write\Bin;
    WriteRawBytes logFile, rawOut \NoOfBytes:=RawBytesLen(rawOut);
    Close logFile;
    Open "HOME:" \File:="cycle.bin", logFile \Read\Bin;
    ReadRawBytes logFile, rawIn;
    nBytesRead := RawBytesLen(rawIn);
    Close logFile;
    Open "HOME:" \File:="recipe.txt", textFile \Read;
    line := ReadStr(textFile);
    IF line = EOF THEN
      bAtEnd := TRUE;
    ELSE
      bGotLine := TRUE;
    ENDIF
    Close textFile;
  ENDPROC
ENDMODULE
