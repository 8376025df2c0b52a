! Palletizing cell, written the way robot code is found in the wild:
! mixed case, comments everywhere, aggregates spread over lines.
MODULE Palletizer (SYSMODULE, NOVIEW)

  LOCAL RECORD layer
    num rows;
    num cols;
    pos pitch;
  ENDRECORD

  LOCAL ALIAS num counter;

  PERS tooldata tGripper := [TRUE,
                             [[0, 0, 125.5], [1, 0, 0, 0]],
                             [2.5, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
  LOCAL PERS wobjdata wPallet := [FALSE, TRUE, "",
      [[1200, -300, 150], [1, 0, 0, 0]],
      [[0, 0, 0], [1, 0, 0, 0]]];
  TASK PERS num nLayerDone := 0;
  LOCAL CONST layer lyStd := [3, 4, [250, 200, 180.]];
  VAR robtarget pStack{3, 4} ;
  CONST num grid{2, 2, 2} := [[[1, 2], [3, 4]], [[5, 6], [7, 8]]];
  var num nCount:=0;
  Pers Num quat{4} := [1, 0, 0, 0];
  CONST num MASK := 0xFF;
  CONST num FLAGS := 0b1010 + 0o17 + 0X1f;
  CONST num SMALL := 1E-3 + .5 + 1. + 2.5e+2 + 9E9;
  VAR string sMsg := "Palette fertig: ""OK"" \\ \41\42";
  VAR num größe := 3;
  VAR intnum irStop;
  VAR signaldi diStop;

  proc main()
    var num row;
    var num col;
    CONNECT irStop WITH StopTrap;
    ISignalDI diStop, 1, irStop;
    ConfL \Off;
    FOR row FROM 1 TO lyStd.rows DO
      FOR col FROM lyStd.cols TO 1 STEP -1 DO
        PlaceOne row, col \Slow;
        PlaceOne row, col, \Slow;
        nCount := nCount + 1;
      ENDFOR
    ENDFOR
    IF nCount MOD 12 = 0 Incr nLayerDone;
    IF nCount > 100 THEN
      TPWrite sMsg;
    ELSEIF nCount > 50 THEN
      TPWrite "half"\Num:=nCount;
    ELSEIF nCount > 10 THEN
      TPWrite "some", \Num:=nCount;
    ELSE
      TPWrite "few";
    ENDIF
    größe := größe * -1;
    nCount := -nCount * 2 + 1 - (3 DIV 2);
    WaitUntil diStop = 0 AND NOT (nCount < 0) \MaxTime:=5 \TimeFlag:=bTimeout;
  ENDPROC

  LOCAL PROC PlaceOne(num r, num c \switch Slow | switch Fast, \VAR num Result)
    VAR robtarget pTarget;
    pTarget := Offs(pStack{r, c}, 0, 0, lyStd.pitch.z);
    MoveJ \Conc, pTarget, v1000, z50, tGripper \WObj:=wPallet;
    IF Present(Slow) THEN
      MoveL pStack{r, c}, v100, fine, tGripper \WObj:=wPallet;
    ELSE
      MoveL ToPoint:=pStack{r, c}, Speed:=v500, Zone:=fine, Tool:=tGripper \WObj:=wPallet;
    ENDIF
    Report \Result?Result;
    IF Present(Result) Result := 1;
  BACKWARD
    MoveL pTarget, v100, fine, tGripper \WObj:=wPallet;
  ERROR (ERR_PATH_STOP, 42)
    IF ERRNO = ERR_PATH_STOP RETRY;
    TRYNEXT;
  UNDO
    nCount := nCount - 1;
  ENDPROC

  LOCAL PROC Report(\VAR num Result)
    IF Present(Result) Result := 0;
  ENDPROC

  FUNC num Sum(num values{*}, num table{*,*}, INOUT num acc, PERS num total)
    VAR num s := 0;
    FOR i FROM 1 TO Dim(values, 1) DO
      s := s + values{i};
    ENDFOR
    RETURN s + table{1, 1};
  ERROR
    RETURN 0;
  ENDFUNC

  FUNC bool IsSafe()
    RETURN NOT OpMode() = OP_MAN_PROG;
  ENDFUNC

  TRAP StopTrap
    StopMove;
    GOTO done;
    nCount := 0;
    done:
    StartMove;
  ERROR (LONG_JMP_ALL_ERR)
    EXIT;
  ENDTRAP

  PROC CallByName(string name)
    % name % nCount, 2 \Slow;
    %"Place" + "One"%;
    RAISE;
  ENDPROC
ENDMODULE
