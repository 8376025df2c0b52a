MODULE CellData
  CONST robtarget pHome := [[500,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPick := [[0,0,20],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST robtarget pPlace := [[200,100,20],[0,0,1,0],[-1,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  CONST jointtarget jSafe := [[0,-20,20,0,60,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  LOCAL VAR iodev logFile;

  PROC LogLine(string text)
    IF NOT bLogEnabled RETURN;
    Open "HOME:" \File:="cell.log", logFile \Append;
    Write logFile, text \Num:=nPartsTotal;
    Close logFile;
  ERROR
    IF ERRNO = ERR_FILEOPEN THEN
      Close logFile;
      RETRY;
    ENDIF
  ENDPROC
ENDMODULE
