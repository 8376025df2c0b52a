MODULE ros_socket
  ! Socket task of a ROS-style motion server: text trajectory points
  ! "<seq> <j1> ... <j6>"; seq -1 starts a trajectory, -3 ends it (the motion task
  ! runs it), -4 stops; other seq values are points.
  LOCAL VAR socketdev serverSocket;
  LOCAL VAR socketdev clientSocket;
  LOCAL VAR num received := 0;

  PROC main()
    VAR string line;
    VAR num seq;
    VAR jointtarget point;
    StartServer 11000;
    WHILE TRUE DO
      SocketReceive clientSocket \Str:=line \Time:=WAIT_MAX;
      IF ParsePoint(line, seq, point) THEN
        received := (received + 1) MOD 3;
        TEST seq
        CASE SEQ_START:
          WaitUntil NOT trajReady;
          trajSize := 0;
          AddPoint point;
        CASE SEQ_END:
          AddPoint point;
          trajReady := TRUE;
        CASE SEQ_STOP:
          WaitUntil NOT trajReady;
          trajSize := 0;
        DEFAULT:
          AddPoint point;
        ENDTEST
      ENDIF
    ENDWHILE
  ENDPROC

  LOCAL PROC StartServer(num port)
    SocketCreate serverSocket;
    SocketBind serverSocket, "127.0.0.1", port;
    SocketListen serverSocket;
    SocketAccept serverSocket, clientSocket \Time:=WAIT_MAX;
  ENDPROC

  LOCAL FUNC bool ParsePoint(string text, INOUT num seq, INOUT jointtarget point)
    VAR num at := 1;
    VAR num next;
    VAR num values{7};
    FOR i FROM 1 TO 7 DO
      next := StrFind(text, at, " ");
      IF NOT StrToVal(StrPart(text, at, next - at), values{i}) RETURN FALSE;
      at := next + 1;
    ENDFOR
    seq := values{1};
    point.robax := [values{2}, values{3}, values{4}, values{5}, values{6}, values{7}];
    point.extax := [9E9, 9E9, 9E9, 9E9, 9E9, 9E9];
    RETURN TRUE;
  ERROR
    RETURN FALSE;
  ENDFUNC

  LOCAL PROC AddPoint(jointtarget point)
    IF trajSize >= TRAJ_MAX OR trajReady THEN
      ErrWrite \W, "ROS motion server", "Too many trajectory points";
    ELSE
      WaitTestAndSet trajLock;
      Incr trajSize;
      trajBuffer{trajSize} := point;
      trajLock := FALSE;
    ENDIF
  ENDPROC
ENDMODULE
