MODULE PalletLines
    ! A PLC gives the pallet line as a group input; the code stores it in a PERS that
    ! other tasks may read (no exact default) and branches on 1, 2 and 3. The check takes
    ! 0..4 and names them; line 4 is no known line, and the program stops with an error.
    PERS num nLine := 0;
    VAR num placed := 0;

    PROC main()
        nLine := giLine;
        TEST nLine
        CASE 1:
            placed := 1;
        CASE 2:
            placed := 2;
        CASE 3:
            placed := 3;
        DEFAULT:
            IF nLine <> 0 RAISE 10;
        ENDTEST
    ENDPROC
ENDMODULE
