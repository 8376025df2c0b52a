MODULE SocketFieldCount
    ! A PC sends "CODE P1 P2 ... #": the code and each parameter are cut at spaces and
    ! parsed with StrToVal in a loop that counts the parameters (the pattern of open_abb).
    ! Each command checks its number of parameters.  A message with the right count for
    ! each command ("1 1 1 1 #" for CASE 1) is tried as a probe, one at a time; "3 3 #"
    ! (a code no CASE names) takes the DEFAULT.
    VAR socketdev server;
    VAR socketdev client;
    VAR string received := "";
    VAR num code := -1;
    VAR num nParams := 0;
    VAR num params{4};
    VAR num done := 0;

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
            next := StrMatch(msg, ind, " ") + 1;
            ok := StrToVal(StrPart(msg, ind, next - ind - 1), code);
            ind := next;
            WHILE finished = FALSE DO
                IF ind <= StrLen(msg) THEN
                    next := StrMatch(msg, ind, " ") + 1;
                ELSE
                    next := ending + 1;
                ENDIF
                IF next > ending OR indParam > 4 THEN
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
            TEST code
            CASE 1:
                IF nParams = 3 THEN
                    done := 13;
                ELSE
                    done := 10;
                ENDIF
            CASE 2:
                IF nParams = 0 THEN
                    done := 20;
                ELSE
                    done := 21;
                ENDIF
            DEFAULT:
                done := -1;
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
