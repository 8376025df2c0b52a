MODULE FörderZähler
    ! A conveyor counter with German identifiers, saved as UTF-8 without a byte order
    ! mark, as RobotWare 7 and today's editors save modules. RAPID letters are those of
    ! ISO 8859-1, so ä, ö, ü and ß are letters of identifiers. Written for rapidmc's
    ! survey round 5.
    VAR num nZähler := 0;
    CONST num nGröße := 3;

    PROC main()
        WHILE nZähler < nGröße DO
            Teil_Übernehmen;
        ENDWHILE
        TPWrite "Förderband leer: " \Num:=nZähler;
    ENDPROC

    PROC Teil_Übernehmen()
        nZähler := nZähler + 1;
        IF nZähler = nGröße GOTO fertig;
        RETURN;
        fertig:
        TPWrite "Größe erreicht";
    ENDPROC
ENDMODULE
