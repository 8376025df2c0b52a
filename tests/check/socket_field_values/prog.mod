MODULE SocketFieldValues
    ! A PC sends "CODE ID P1 P2 ... #": the code, an id the server only echoes, then the
    ! parameters, each cut at spaces and parsed with StrToVal in a loop that counts them
    ! (the pattern of mcubelab's abb_robotnode).  Command 9 tells its first parameter
    ! apart (1: fine point, else a zone), command 12 takes a pose and checks that its
    ! quaternion is a unit one.  The probes try each command with its count of parameters
    ! after one more field (the id), with the first parameter at each value compared
    ! ("9 1 2 1 1 1 #"), and a pose of zeros ending in the identity rotation
    ! ("12 1 0 0 0 1 0 0 0 #"), so every branch below is reached.
    VAR socketdev server;
    VAR socketdev client;
    VAR string received := "";
    VAR string id := "";
    VAR num code := -1;
    VAR num nParams := 0;
    VAR num params{8};
    VAR num done := 0;

    FUNC num NextSpace(string msg, num ind)
        IF ind > StrLen(msg) RETURN StrLen(msg) + 2;
        RETURN StrMatch(msg, ind, " ") + 1;
    ENDFUNC

    PROC Parse(string msg)
        VAR num ending;
        VAR num ind := 1;
        VAR num next;
        VAR num indParam := 1;
        VAR bool ok;
        VAR bool finished := FALSE;
        ending := StrMatch(msg, 1, "#");
        IF ending > StrLen(msg) THEN
            nParams := -1;
        ELSE
            next := NextSpace(msg, ind);
            ok := StrToVal(StrPart(msg, ind, next - ind - 1), code);
            ind := next;
            next := NextSpace(msg, ind);
            IF next <= ending id := StrPart(msg, ind, next - ind - 1);
            ind := next;
            WHILE finished = FALSE DO
                next := NextSpace(msg, ind);
                IF next > ending OR indParam > 8 THEN
                    finished := TRUE;
                ELSE
                    ok := StrToVal(StrPart(msg, ind, next - ind - 1), params{indParam});
                    indParam := indParam + 1;
                    ind := next;
                ENDIF
            ENDWHILE
            nParams := indParam - 1;
        ENDIF
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 5000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=received \Time:=WAIT_MAX;
            Parse received;
            done := 0;
            TEST code
            CASE 9:
                IF nParams = 4 THEN
                    IF params{1} = 1 THEN
                        done := 91;
                    ELSE
                        done := 92;
                    ENDIF
                ENDIF
            CASE 12:
                IF nParams = 7 THEN
                    IF Abs(1 - Sqrt(params{4} * params{4} + params{5} * params{5}
                                    + params{6} * params{6} + params{7} * params{7})) > 0.001 THEN
                        done := 120;
                    ELSE
                        done := 121;
                    ENDIF
                ENDIF
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
