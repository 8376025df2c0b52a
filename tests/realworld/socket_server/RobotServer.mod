MODULE RobotServer
  ! A line-protocol robot server: "<command> <arg> ... #" per message,
  ! the reply is "<command> <status> <data>".
  VAR socketdev server;
  VAR socketdev client;
  VAR string peer;
  VAR string request;
  VAR string reply;
  VAR num command;
  VAR num args{4};
  VAR num nArgs;
  VAR num nMoves := 0;
  VAR bool connected := FALSE;
  VAR robtarget target;
  PERS tooldata tPen := [TRUE,[[0,0,120],[1,0,0,0]],[0.5,[0,0,40],[1,0,0,0],0,0,0]];
  CONST num REPLY_OK := 1;
  CONST num REPLY_BAD := 0;

  PROC Listen()
    SocketCreate server;
    SocketBind server, "127.0.0.1", 5000;
    SocketListen server;
    SocketAccept server, client \ClientAddress:=peer \Time:=WAIT_MAX;
    connected := TRUE;
    TPWrite "client " + peer;
  ENDPROC

  PROC Decode(string text)
    VAR num at := 1;
    VAR num upto;
    VAR num stop;
    VAR bool ok;
    nArgs := 0;
    command := -1;
    stop := StrMatch(text, 1, "#");
    IF stop > StrLen(text) RETURN;
    upto := StrMatch(text, at, " ");
    ok := StrToVal(StrPart(text, at, upto - at), command);
    IF NOT ok command := -1;
    at := upto + 1;
    WHILE at < stop AND nArgs < 4 DO
      upto := StrMatch(text, at, " ");
      Incr nArgs;
      ok := StrToVal(StrPart(text, at, upto - at), args{nArgs});
      at := upto + 1;
    ENDWHILE
  ENDPROC

  PROC main()
    Listen;
    WHILE TRUE DO
      SocketReceive client \Str:=request \Time:=WAIT_MAX;
      Decode request;
      reply := NumToStr(command, 0) + " ";
      TEST command
      CASE 0:
        SocketSend client \Str:=reply + "bye";
        SocketClose client;
        SocketClose server;
        EXIT;
      CASE 1:
        reply := reply + NumToStr(REPLY_OK, 0) + " pong";
      CASE 2:
        IF nArgs = 3 THEN
          target := [[args{1},args{2},args{3}],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
          MoveL target, v200, fine, tPen;
          Incr nMoves;
          reply := reply + NumToStr(REPLY_OK, 0);
        ELSE
          reply := reply + NumToStr(REPLY_BAD, 0);
        ENDIF
      CASE 3:
        reply := reply + NumToStr(REPLY_OK, 0) + " " + NumToStr(CPos(\Tool:=tPen).x, 1);
      DEFAULT:
        reply := reply + NumToStr(REPLY_BAD, 0);
      ENDTEST
      SocketSend client \Str:=reply;
    ENDWHILE
  ERROR (LONG_JMP_ALL_ERR)
    IF ERRNO = ERR_SOCK_CLOSED THEN
      TPWrite "client left, listening again";
      connected := FALSE;
      SocketClose client;
      SocketClose server;
      Listen;
      RETRY;
    ENDIF
    RAISE;
  ENDPROC
ENDMODULE
