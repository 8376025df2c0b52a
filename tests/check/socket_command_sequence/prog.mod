MODULE SocketCommandSequence
    ! A PC sends "CODE ID P1 P2 ... #" as in socket_field_values (open_abb's protocol):
    ! command 30 adds a point to a buffer (at most two), 31 clears it, 33 moves through the
    ! points added (a WHILE: a FOR up to 0 would run, counting down).
    ! The loop under 33 runs only after a 30: no one message reaches it, and the commands'
    ! messages are probes (tried one at a time).  Command 30 writes what the WHILE of 33
    ! reads, so the two are also a probe together ('30 1 1 1 1 #' with '33 1 #'), whose
    ! search sends 30 and then 33 and reaches "moved := moved + 1".
    VAR socketdev server;
    VAR socketdev client;
    VAR string received := "";
    VAR string id := "";
    VAR num code := -1;
    VAR num nParams := 0;
    VAR num params{8};
    VAR num done := 0;
    VAR num bufferPos := 0;
    VAR num moved := 0;

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
            TEST code
            CASE 30:
                IF nParams = 3 THEN
                    IF bufferPos < 2 bufferPos := bufferPos + 1;
                ENDIF
            CASE 31:
                IF nParams = 0 bufferPos := 0;
            CASE 33:
                IF nParams = 0 THEN
                    WHILE moved < bufferPos DO
                        moved := moved + 1;
                    ENDWHILE
                    moved := 0;
                ENDIF
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
