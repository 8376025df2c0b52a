MODULE SocketSplitFields
    ! A client's message "F|SM|[175,0,147]" is split at a separator the caller passes
    ! (strSplit msg, "|", parts, n) into a string array; the first field must be "F", the
    ! second names the command, the third holds the target.  Each command is offered in
    ! the second field after "F" ('F|SM'), and SM's target in the third ('F|SM|[1,2,3]').
    VAR socketdev client;
    VAR string received := "";
    VAR string parts{4};
    VAR num count := 0;
    VAR pos target := [0, 0, 0];
    VAR num action := 0;
    VAR bool ok := FALSE;

    PROC main()
        SocketCreate client;
        SocketConnect client, "10.0.0.2", 5000 \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=received \Time:=WAIT_MAX;
            strSplit received, "|", parts, count;
            IF parts{1} = "F" THEN
                TEST parts{2}
                CASE "SM":
                    ok := StrToVal(parts{3}, target);
                    IF ok action := 1;
                CASE "ST":
                    action := 2;
                ENDTEST
            ENDIF
        ENDWHILE
    ENDPROC

    PROC strSplit(string text, string split, VAR string result{*}, VAR num n)
        VAR num start := 1;
        VAR num next := 1;
        FOR i FROM 1 TO Dim(result, 1) DO
            result{i} := "";
        ENDFOR
        n := 0;
        FOR i FROM 1 TO Dim(result, 1) DO
            next := StrFind(text, start, split);
            result{i} := StrPart(text, start, next - start);
            n := n + 1;
            IF next > StrLen(text) RETURN;
            start := next + 1;
        ENDFOR
    ENDPROC
ENDMODULE
