MODULE ROS_motionServer
  ! Text trajectory points "<seq> <j1> <j2> <j3> <j4> <j5> <j6>"; seq -1 starts a
  ! trajectory, -3 ends (and runs) it, -4 stops; other seq values are points.
  LOCAL VAR socketdev serverSocket;
  LOCAL VAR socketdev clientSocket;
  LOCAL VAR num received := 0;
  LOCAL VAR rawbytes state;

  PROC main()
    VAR string line;
    VAR num seq;
    VAR jointtarget point;
    received := 0;
    StartServer 11000;
    WHILE TRUE DO
      SocketReceive clientSocket \Str:=line \Time:=5;
      IF ParsePoint(line, seq, point) THEN
        Incr received;
        TEST seq
        CASE SEQ_START:
          trajSize := 0;
          AddPoint point;
        CASE SEQ_END:
          AddPoint point;
          RunTrajectory;
          SendState;
        CASE SEQ_STOP:
          trajSize := 0;
        DEFAULT:
          AddPoint point;
        ENDTEST
      ENDIF
    ENDWHILE
  ERROR (ERR_SOCK_TIMEOUT, ERR_SOCK_CLOSED)
    SkipWarn;
    ErrWrite \W, "ROS motion server", "Connection lost. Restarting.";
    trajSize := 0;
    ExitCycle;
  UNDO
    IF SocketGetStatus(clientSocket) <> SOCKET_CLOSED SocketClose clientSocket;
    IF SocketGetStatus(serverSocket) <> SOCKET_CLOSED SocketClose serverSocket;
  ENDPROC

  LOCAL PROC StartServer(num port)
    IF SocketGetStatus(serverSocket) = SOCKET_CLOSED SocketCreate serverSocket;
    IF SocketGetStatus(serverSocket) = SOCKET_CREATED SocketBind serverSocket, GetSysInfo(\LanIp), port;
    IF SocketGetStatus(serverSocket) = SOCKET_BOUND SocketListen serverSocket;
    SocketAccept serverSocket, clientSocket \Time:=WAIT_MAX;
    TPWrite "[MotionServer] client connected";
  ERROR
    RAISE;
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
    IF trajSize >= TRAJ_MAX THEN
      ErrWrite \W, "ROS motion server", "Too many trajectory points";
      trajSize := 0;
    ELSE
      WaitTestAndSet trajLock;
      Incr trajSize;
      trajBuffer{trajSize} := point;
      trajLock := FALSE;
    ENDIF
  ENDPROC

  LOCAL PROC RunTrajectory()
    FOR i FROM 1 TO trajSize DO
      MoveAbsJ trajBuffer{i}, v1000, z10, tool0;
      Incr nExecuted;
    ENDFOR
    trajSize := 0;
  ENDPROC

  LOCAL PROC SendState()
    VAR jointtarget now;
    now := CJointT();
    ClearRawBytes state;
    PackRawBytes 8, state, 1, \IntX:=UDINT;
    PackRawBytes nExecuted, state \Network, 5, \IntX:=DINT;
    PackRawBytes now.robax.rax_1, state, 9, \Float4;
    SocketSend clientSocket \RawData:=state;
  ENDPROC
ENDMODULE
