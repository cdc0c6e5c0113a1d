<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>BoneEditCommand</name>
    <message>
        <source>Split Bone %1 of %2</source>
        <translation>Knochen %1 von %2 teilen</translation>
    </message>
    <message>
        <source>Delete Bone %1 of %2</source>
        <translation>Knochen %1 von %2 löschen</translation>
    </message>
    <message>
        <source>%1 in %2 ms: %3 vertices and %4 re-skinned</source>
        <translation>%1 in %2 ms: %3 Vertices und %4 neu gebunden</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 Knochen</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 Knochen</translation>
    </message>
    <message>
        <source>Connect Bone %1 of %2</source>
        <translation>Knochen %1 von %2 verbinden</translation>
    </message>
</context>
<context>
    <name>ClipListCommand</name>
    <message>
        <source>New clip %1 of %2</source>
        <translation>Neuer Clip %1 von %2</translation>
    </message>
    <message>
        <source>Duplicate clip %1 of %2 as %3</source>
        <translation>Clip %1 von %2 als %3 duplizieren</translation>
    </message>
    <message>
        <source>Rename clip %1 of %2 to %3</source>
        <translation>Clip %1 von %2 in %3 umbenennen</translation>
    </message>
    <message>
        <source>Delete clip %1 of %2</source>
        <translation>Clip %1 von %2 löschen</translation>
    </message>
    <message>
        <source>Play clip %1 on %2</source>
        <translation>Clip %1 auf %2 abspielen</translation>
    </message>
</context>
<context>
    <name>CreatePartCommand</name>
    <message>
        <source>Part %1</source>
        <translation>Teil %1</translation>
    </message>
    <message>
        <source>Create %1</source>
        <translation>%1 erstellen</translation>
    </message>
</context>
<context>
    <name>CutPartCommand</name>
    <message>
        <source>Cut %1</source>
        <translation>%1 schneiden</translation>
    </message>
    <message>
        <source>%1 cut</source>
        <translation>%1 abgeschnitten</translation>
    </message>
</context>
<context>
    <name>DeleteKeyCommand</name>
    <message>
        <source>Delete key of %1 at %2 s</source>
        <translation>Schlüsselbild von %1 bei %2 s löschen</translation>
    </message>
</context>
<context>
    <name>DeletePartCommand</name>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
</context>
<context>
    <name>DraggedRigCarry</name>
    <message numerus="yes">
        <source>the rotations of %n joint(s)</source>
        <translation>
            <numerusform>die Drehung von %n Gelenk</numerusform>
            <numerusform>die Drehungen von %n Gelenken</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n pin(s)</source>
        <translation>
            <numerusform>%n Fixierung</numerusform>
            <numerusform>%n Fixierungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n key(s)</source>
        <translation>
            <numerusform>%n Schlüsselbild</numerusform>
            <numerusform>%n Schlüsselbilder</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the rotations of joint(s) %1 (in the merged skeleton they would turn other bones)</source>
        <translation>
            <numerusform>die Drehung des Gelenks %1 (im zusammengeführten Skelett würde sie andere Knochen drehen)</numerusform>
            <numerusform>die Drehungen der Gelenke %1 (im zusammengeführten Skelett würden sie andere Knochen drehen)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>the pin(s) of joint(s) %1 (pruned)</source>
        <translation>
            <numerusform>die Fixierung des Gelenks %1 (entfernt)</numerusform>
            <numerusform>die Fixierungen der Gelenke %1 (entfernt)</numerusform>
        </translation>
    </message>
    <message>
        <source>its root offset</source>
        <translation>seinen Wurzelversatz</translation>
    </message>
    <message>
        <source>from %1: </source>
        <translation>von %1: </translation>
    </message>
    <message>
        <source>kept %1</source>
        <translation>%1 behalten</translation>
    </message>
    <message>
        <source>dropped %1</source>
        <translation>%1 verworfen</translation>
    </message>
    <message>
        <source>; its keys now play at the target&apos;s frame rate and interpolation</source>
        <translation>; seine Schlüsselbilder laufen jetzt mit Bildrate und Interpolation des Ziels</translation>
    </message>
</context>
<context>
    <name>EngineMessage</name>
    <message>
        <source>Point %1 of the stroke (counting from 0) is %2, which is not a finite number: the sketch data is corrupt. Redraw the stroke.</source>
        <translation>Punkt %1 des Strichs (ab 0 gezählt) ist %2, keine endliche Zahl: die Skizzendaten sind beschädigt. Zeichnen Sie den Strich neu.</translation>
    </message>
    <message>
        <source>The stroke has only 1 distinct point; a silhouette needs at least 3 points that enclose an area. Draw a closed outline.</source>
        <translation>Der Strich hat nur einen einzigen Punkt; eine Silhouette braucht mindestens 3 Punkte, die eine Fläche umschließen. Zeichnen Sie einen geschlossenen Umriss.</translation>
    </message>
    <message>
        <source>The stroke has only %1 distinct points; a silhouette needs at least 3 points that enclose an area. Draw a closed outline.</source>
        <translation>Der Strich hat nur %1 verschiedene Punkte; eine Silhouette braucht mindestens 3 Punkte, die eine Fläche umschließen. Zeichnen Sie einen geschlossenen Umriss.</translation>
    </message>
    <message>
        <source>The stroke has %1 points but only %2 distinct positions; the other %3 repeat them, which is too little to describe a silhouette. Draw the outline as one continuous stroke.</source>
        <translation>Der Strich hat %1 Punkte, aber nur %2 verschiedene Positionen; die übrigen %3 wiederholen sie, zu wenig für eine Silhouette. Zeichnen Sie den Umriss in einem durchgehenden Strich.</translation>
    </message>
    <message>
        <source>The stroke is too long for its size: at the requested spacing its outline would need more than %1 points. Draw a simpler outline or use a larger spacing.</source>
        <translation>Der Strich ist für seine Größe zu lang: beim gewünschten Abstand bräuchte sein Umriss mehr als %1 Punkte. Zeichnen Sie einen einfacheren Umriss oder wählen Sie einen größeren Abstand.</translation>
    </message>
    <message>
        <source>All points of the stroke lie on (nearly) one straight line, so it encloses no area. Draw a closed silhouette.</source>
        <translation>Alle Punkte des Strichs liegen (fast) auf einer Geraden, er umschließt also keine Fläche. Zeichnen Sie eine geschlossene Silhouette.</translation>
    </message>
    <message>
        <source>The stroke crosses itself near %1: draw a silhouette that does not cross itself.</source>
        <translation>Der Strich kreuzt sich selbst bei %1: zeichnen Sie eine Silhouette ohne Überkreuzung.</translation>
    </message>
    <message>
        <source>The stroke encloses almost no area (it runs back along itself). Draw a silhouette with some width.</source>
        <translation>Der Strich umschließt fast keine Fläche (er läuft auf sich selbst zurück). Zeichnen Sie eine Silhouette mit etwas Breite.</translation>
    </message>
    <message>
        <source>The stroke&apos;s coordinates are too large to process; scale the sketch down.</source>
        <translation>Die Koordinaten des Strichs sind zu groß zum Verarbeiten; skalieren Sie die Skizze kleiner.</translation>
    </message>
    <message>
        <source>the outline touches itself at (%1, %2)</source>
        <translation>der Umriss berührt sich selbst bei (%1, %2)</translation>
    </message>
    <message>
        <source>the outline crosses itself: draw a silhouette that does not cross itself</source>
        <translation>der Umriss kreuzt sich selbst: zeichnen Sie eine Silhouette ohne Überkreuzung</translation>
    </message>
    <message>
        <source>an outline needs at least three points</source>
        <translation>ein Umriss braucht mindestens drei Punkte</translation>
    </message>
    <message>
        <source>the outline has repeated points</source>
        <translation>der Umriss hat doppelte Punkte</translation>
    </message>
    <message>
        <source>the outline encloses no area</source>
        <translation>der Umriss umschließt keine Fläche</translation>
    </message>
    <message>
        <source>the outline is too simple to have an axis: draw a larger, rounder shape</source>
        <translation>der Umriss ist zu einfach für eine Achse: zeichnen Sie eine größere, rundere Form</translation>
    </message>
    <message>
        <source>the sketch is %1 across; sizes from %2 to %3 are supported</source>
        <translation>die Skizze ist %1 groß; unterstützt werden Größen von %2 bis %3</translation>
    </message>
    <message>
        <source>the sketch lies too far from the origin for its size: near %1 doubles are %2 apart, more than a millionth of its edges (%3); move it within %4 of the origin</source>
        <translation>die Skizze liegt für ihre Größe zu weit vom Ursprung: bei %1 liegen Gleitkommazahlen %2 auseinander, mehr als ein Millionstel ihrer Kanten (%3); rücken Sie sie auf %4 heran</translation>
    </message>
    <message>
        <source>the edge length %1 is too small for this sketch: it would give about %2 vertices, more than the %3 allowed; use 0 (automatic: %4) or an edge length of at least %5</source>
        <translation>die Kantenlänge %1 ist für diese Skizze zu klein: sie ergäbe etwa %2 Vertices, mehr als die erlaubten %3; nehmen Sie 0 (automatisch: %4) oder mindestens %5</translation>
    </message>
    <message>
        <source>the surface has a vertex with a non-finite coordinate; the sketch&apos;s numbers are beyond what double precision can build</source>
        <translation>die Oberfläche hat einen Vertex mit nicht endlicher Koordinate; die Zahlen der Skizze liegen jenseits dessen, was doppelte Genauigkeit bauen kann</translation>
    </message>
    <message>
        <source>the surface has %1 degenerate faces; double precision cannot build this sketch at its position and size</source>
        <translation>die Oberfläche hat %1 entartete Flächen; mit doppelter Genauigkeit lässt sich diese Skizze an ihrer Position und in ihrer Größe nicht bauen</translation>
    </message>
    <message>
        <source>the target edge length must be 0 (automatic) or a positive length</source>
        <translation>die Ziel-Kantenlänge muss 0 (automatisch) oder eine positive Länge sein</translation>
    </message>
    <message>
        <source>least-squares smoothing failed: the surface system could not be factored</source>
        <translation>die Glättung nach kleinsten Quadraten ist fehlgeschlagen: das Gleichungssystem der Oberfläche ließ sich nicht faktorisieren</translation>
    </message>
    <message>
        <source>least-squares smoothing failed: the surface system has no finite solution</source>
        <translation>die Glättung nach kleinsten Quadraten ist fehlgeschlagen: das Gleichungssystem der Oberfläche hat keine endliche Lösung</translation>
    </message>
    <message>
        <source>Only rigged parts can be merged; rig the imported mesh first.</source>
        <translation>Nur geriggte Teile lassen sich zusammenführen; riggen Sie das importierte Netz zuerst.</translation>
    </message>
    <message>
        <source>The merge gave an invalid part (%1); nothing was changed.</source>
        <translation>Das Zusammenführen ergab ein ungültiges Teil (%1); nichts wurde geändert.</translation>
    </message>
    <message>
        <source>The dragged part has no joint %1.</source>
        <translation>Das gezogene Teil hat kein Gelenk %1.</translation>
    </message>
    <message>
        <source>The target part has no joint %1.</source>
        <translation>Das Zielteil hat kein Gelenk %1.</translation>
    </message>
    <message>
        <source>The target part has no bone %1.</source>
        <translation>Das Zielteil hat keinen Knochen %1.</translation>
    </message>
    <message>
        <source>The two joints to connect are at the same place; snap them instead.</source>
        <translation>Die beiden zu verbindenden Gelenke liegen an derselben Stelle; fügen Sie sie stattdessen zusammen.</translation>
    </message>
    <message>
        <source>One of the surfaces intersects itself, so the parts cannot be merged. Rebuild it with a larger edge length or smoothing, then merge again.</source>
        <translation>Eine der Oberflächen schneidet sich selbst, daher lassen sich die Teile nicht zusammenführen. Bauen Sie sie mit größerer Kantenlänge oder Glättung neu und führen Sie sie dann erneut zusammen.</translation>
    </message>
    <message>
        <source>The merged surface would not be a manifold (the parts touch at a point or along a line). Move the dragged part so that it overlaps the other one, then merge again.</source>
        <translation>Die zusammengeführte Oberfläche wäre nicht mannigfaltig (die Teile berühren sich in einem Punkt oder einer Linie). Schieben Sie das gezogene Teil in das andere und führen Sie erneut zusammen.</translation>
    </message>
    <message>
        <source>The parts do not touch. Drag one part so that it overlaps the other, then merge.</source>
        <translation>Die Teile berühren sich nicht. Ziehen Sie ein Teil so, dass es das andere überlappt, und führen Sie sie dann zusammen.</translation>
    </message>
    <message>
        <source>One part lies entirely inside the other, so merging would only delete it. Drag it so that it sticks out of the other part, then merge.</source>
        <translation>Ein Teil liegt vollständig im anderen, Zusammenführen würde es nur löschen. Ziehen Sie es so, dass es aus dem anderen Teil herausragt, und führen Sie dann zusammen.</translation>
    </message>
    <message>
        <source>The local skin weights could not be solved; use the global re-computation.</source>
        <translation>Die lokalen Skin-Gewichte ließen sich nicht lösen; verwenden Sie die globale Neuberechnung.</translation>
    </message>
    <message>
        <source>Only rigged parts can be cut; rig the imported mesh first.</source>
        <translation>Nur geriggte Teile lassen sich schneiden; riggen Sie das importierte Netz zuerst.</translation>
    </message>
    <message>
        <source>The cut needs a plane: a finite point and a non-zero normal.</source>
        <translation>Der Schnitt braucht eine Ebene: einen endlichen Punkt und eine Normale ungleich null.</translation>
    </message>
    <message>
        <source>The cut&apos;s stroke has a point that is not a finite number.</source>
        <translation>Der Schnittstrich hat einen Punkt, der keine endliche Zahl ist.</translation>
    </message>
    <message>
        <source>The cut does not cross the part. Draw it across the part, from one side of its outline to the other.</source>
        <translation>Der Schnitt kreuzt das Teil nicht. Ziehen Sie ihn quer über das Teil, von einer Seite seines Umrisses zur anderen.</translation>
    </message>
    <message>
        <source>The cut crosses the part more than once (it would make %1 pieces). Cut where it crosses only once, or cut again.</source>
        <translation>Der Schnitt kreuzt das Teil mehr als einmal (es entstünden %1 Stücke). Schneiden Sie dort, wo er nur einmal kreuzt, oder schneiden Sie noch einmal.</translation>
    </message>
    <message>
        <source>The cut leaves two pieces on the same side of its plane; cut elsewhere.</source>
        <translation>Der Schnitt lässt zwei Stücke auf derselben Seite seiner Ebene; schneiden Sie an anderer Stelle.</translation>
    </message>
    <message>
        <source>The cut leaves a piece without a bone. Cut across a bone, nearer the middle of the part.</source>
        <translation>Der Schnitt lässt ein Stück ohne Knochen zurück. Schneiden Sie quer durch einen Knochen, näher an der Mitte des Teils.</translation>
    </message>
    <message>
        <source>The cut leaves a piece whose skeleton is not one tree; cut elsewhere.</source>
        <translation>Der Schnitt lässt ein Stück zurück, dessen Skelett kein einzelner Baum ist; schneiden Sie an anderer Stelle.</translation>
    </message>
    <message>
        <source>The patch&apos;s skin weights could not be solved; cut elsewhere.</source>
        <translation>Die Skin-Gewichte der Schnittfläche ließen sich nicht lösen; schneiden Sie an anderer Stelle.</translation>
    </message>
    <message>
        <source>The cut gave an invalid piece (%1); nothing was changed.</source>
        <translation>Der Schnitt ergab ein ungültiges Stück (%1); nichts wurde geändert.</translation>
    </message>
    <message>
        <source>A cut needs a stroke of two points or more and a view direction.</source>
        <translation>Ein Schnitt braucht einen Strich aus mindestens zwei Punkten und eine Blickrichtung.</translation>
    </message>
    <message>
        <source>The cut&apos;s stroke must not start and end at the same point.</source>
        <translation>Der Schnittstrich darf nicht am selben Punkt beginnen und enden.</translation>
    </message>
    <message>
        <source>The bone edit gave an invalid part (%1); nothing was changed.</source>
        <translation>Die Knochenbearbeitung ergab ein ungültiges Teil (%1); nichts wurde geändert.</translation>
    </message>
    <message>
        <source>The part has no skeleton.</source>
        <translation>Das Teil hat kein Skelett.</translation>
    </message>
    <message>
        <source>The part has no bone %1.</source>
        <translation>Das Teil hat keinen Knochen %1.</translation>
    </message>
    <message>
        <source>That is too close to a joint to split the bone; pick a point nearer its middle.</source>
        <translation>Das liegt zu nah an einem Gelenk, um den Knochen zu teilen; wählen Sie einen Punkt näher an seiner Mitte.</translation>
    </message>
    <message>
        <source>No part of the surface is led by that bone where it would be split.</source>
        <translation>An der Teilungsstelle wird kein Bereich der Oberfläche von diesem Knochen bestimmt.</translation>
    </message>
    <message>
        <source>A part keeps at least one bone; this is its only one.</source>
        <translation>Ein Teil behält mindestens einen Knochen; dies ist sein einziger.</translation>
    </message>
    <message>
        <source>The IK target is not a finite point.</source>
        <translation>Das IK-Ziel ist kein endlicher Punkt.</translation>
    </message>
    <message>
        <source>Cannot pose a skeleton without joints.</source>
        <translation>Ein Skelett ohne Gelenke lässt sich nicht posieren.</translation>
    </message>
    <message>
        <source>Cannot pose a skeleton without a valid root joint.</source>
        <translation>Ein Skelett ohne gültiges Wurzelgelenk lässt sich nicht posieren.</translation>
    </message>
    <message>
        <source>The skeleton has no joint %1.</source>
        <translation>Das Skelett hat kein Gelenk %1.</translation>
    </message>
    <message>
        <source>The pose gives joint %1 a rotation that is not a finite, non-zero quaternion.</source>
        <translation>Die Pose gibt Gelenk %1 eine Rotation, die kein endliches Quaternion ungleich null ist.</translation>
    </message>
    <message>
        <source>The pose&apos;s root translation is not finite.</source>
        <translation>Die Wurzelverschiebung der Pose ist nicht endlich.</translation>
    </message>
    <message>
        <source>There is already a key at exactly %1 s.</source>
        <translation>Bei genau %1 s gibt es bereits ein Schlüsselbild.</translation>
    </message>
    <message>
        <source>There is no key at exactly %1 s.</source>
        <translation>Bei genau %1 s gibt es kein Schlüsselbild.</translation>
    </message>
    <message>
        <source>There is no key at %1 s.</source>
        <translation>Bei %1 s gibt es kein Schlüsselbild.</translation>
    </message>
    <message>
        <source>There is no key at %1 s to move.</source>
        <translation>Bei %1 s gibt es kein Schlüsselbild zum Verschieben.</translation>
    </message>
    <message>
        <source>There is no key at %1 s to delete.</source>
        <translation>Bei %1 s gibt es kein Schlüsselbild zum Löschen.</translation>
    </message>
    <message>
        <source>The clip has no keys.</source>
        <translation>Der Clip hat keine Schlüsselbilder.</translation>
    </message>
    <message>
        <source>Cannot play a clip without keys.</source>
        <translation>Ein Clip ohne Schlüsselbilder lässt sich nicht abspielen.</translation>
    </message>
    <message>
        <source>A key&apos;s pose must have finite, non-zero rotations and a finite translation.</source>
        <translation>Die Pose eines Schlüsselbilds braucht endliche Rotationen ungleich null und eine endliche Verschiebung.</translation>
    </message>
    <message>
        <source>The part has no bone %1 to paint.</source>
        <translation>Das Teil hat keinen Knochen %1 zum Malen.</translation>
    </message>
    <message>
        <source>Bone %1 is locked; unlock it to paint it.</source>
        <translation>Knochen %1 ist gesperrt; entsperren Sie ihn, um ihn zu malen.</translation>
    </message>
    <message>
        <source>A brush needs a finite centre, a positive radius, and a strength and value between 0 and 1.</source>
        <translation>Ein Pinsel braucht einen endlichen Mittelpunkt, einen positiven Radius sowie Stärke und Wert zwischen 0 und 1.</translation>
    </message>
    <message>
        <source>Front faces only needs a finite, non-zero view direction.</source>
        <translation>„Nur Vorderseiten“ braucht eine endliche Blickrichtung ungleich null.</translation>
    </message>
    <message>
        <source>The clean threshold must be at least 0 and below 1.</source>
        <translation>Der Schwellwert zum Bereinigen muss mindestens 0 und kleiner als 1 sein.</translation>
    </message>
    <message>
        <source>A vertex needs at least one influence.</source>
        <translation>Ein Vertex braucht mindestens einen Einfluss.</translation>
    </message>
    <message>
        <source>Smooth All needs a factor from 0 to 1 and 1 to 100 passes.</source>
        <translation>„Alle glätten“ braucht einen Faktor von 0 bis 1 und 1 bis 100 Durchgänge.</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>cannot write %1: the folder %2 does not exist</source>
        <translation>%1 kann nicht geschrieben werden: der Ordner %2 existiert nicht</translation>
    </message>
    <message>
        <source>cannot write %1: it is a folder</source>
        <translation>%1 kann nicht geschrieben werden: es ist ein Ordner</translation>
    </message>
    <message>
        <source>cannot write %1: the file is read-only</source>
        <translation>%1 kann nicht geschrieben werden: die Datei ist schreibgeschützt</translation>
    </message>
    <message>
        <source>cannot write %1: cannot create a file in %2: %3</source>
        <translation>%1 kann nicht geschrieben werden: in %2 lässt sich keine Datei anlegen: %3</translation>
    </message>
    <message>
        <source>cannot write %1: %2 (is the disk full?)</source>
        <translation>%1 kann nicht geschrieben werden: %2 (ist der Datenträger voll?)</translation>
    </message>
    <message>
        <source>cannot write %1: cannot keep its permissions: %2</source>
        <translation>%1 kann nicht geschrieben werden: die Zugriffsrechte lassen sich nicht erhalten: %2</translation>
    </message>
    <message>
        <source>cannot export: there is no part</source>
        <translation>Export nicht möglich: es gibt kein Teil</translation>
    </message>
    <message>
        <source>cannot export part &apos;%1&apos;: it has no surface</source>
        <translation>Teil „%1“ kann nicht exportiert werden: es hat keine Oberfläche</translation>
    </message>
    <message>
        <source>cannot export part &apos;%1&apos;: its skin weights do not match its surface</source>
        <translation>Teil „%1“ kann nicht exportiert werden: seine Skin-Gewichte passen nicht zu seiner Oberfläche</translation>
    </message>
    <message>
        <source>cannot export the clip: the times %1 s and %2 s are too close for 32-bit precision this far from 0 s; move the keys nearer to 0 s or further apart</source>
        <translation>der Clip kann nicht exportiert werden: die Zeiten %1 s und %2 s liegen so weit von 0 s zu nah beieinander für 32-Bit-Genauigkeit; rücken Sie die Schlüssel näher an 0 s oder auseinander</translation>
    </message>
    <message>
        <source>subdivision levels must be from 0 to 4, not %1</source>
        <translation>die Unterteilungsstufen müssen zwischen 0 und 4 liegen, nicht %1</translation>
    </message>
    <message>
        <source>subdividing &apos;%1&apos; %2 times would give over %3 vertices; use fewer levels</source>
        <translation>„%1“ %2-mal zu unterteilen ergäbe über %3 Vertices; verwenden Sie weniger Stufen</translation>
    </message>
    <message>
        <source>decimating needs a target of at least 4 faces, not %1</source>
        <translation>Ausdünnen braucht ein Ziel von mindestens 4 Flächen, nicht %1</translation>
    </message>
    <message>
        <source>the surface is not manifold, so it cannot be decimated</source>
        <translation>die Oberfläche ist nicht mannigfaltig und lässt sich daher nicht ausdünnen</translation>
    </message>
    <message>
        <source>%1 already has a skeleton. Rig parts without one (imported meshes); to start a sketched part&apos;s rig again, use Recompute Weights or Rebuild.</source>
        <translation>%1 hat bereits ein Skelett. Riggen Sie Teile ohne Skelett (importierte Netze); um das Rig eines skizzierten Teils neu aufzubauen, verwenden Sie „Gewichte neu berechnen“ oder „Neu bauen“.</translation>
    </message>
    <message>
        <source>%1 has no surface to rig.</source>
        <translation>%1 hat keine Oberfläche zum Riggen.</translation>
    </message>
    <message>
        <source>The mesh has only %1 usable faces; a rig needs a closed surface that bounds a volume.</source>
        <translation>Das Netz hat nur %1 brauchbare Flächen; ein Rig braucht eine geschlossene Oberfläche, die ein Volumen umschließt.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: %1</source>
        <translation>Im Netz ließ sich kein Skelett finden: %1</translation>
    </message>
    <message>
        <source>Rigging was cancelled.</source>
        <translation>Das Riggen wurde abgebrochen.</translation>
    </message>
    <message>
        <source>joined %1 vertices that sat at the same position (split seams)</source>
        <translation>%1 Vertices an derselben Position verbunden (aufgetrennte Nähte)</translation>
    </message>
    <message>
        <source>removed %1 degenerate faces (no area)</source>
        <translation>%1 entartete Flächen (ohne Fläche) entfernt</translation>
    </message>
    <message>
        <source>removed %1 duplicate faces</source>
        <translation>%1 doppelte Flächen entfernt</translation>
    </message>
    <message>
        <source>removed %1 vertices no face uses</source>
        <translation>%1 von keiner Fläche benutzte Vertices entfernt</translation>
    </message>
    <message>
        <source>split %1 vertices where separate sheets touched</source>
        <translation>%1 Vertices getrennt, an denen sich getrennte Flächenstücke berührten</translation>
    </message>
    <message>
        <source>turned the faces outward (they faced inward)</source>
        <translation>die Flächen nach außen gedreht (sie zeigten nach innen)</translation>
    </message>
    <message>
        <source>filled %1 small holes with %2 new vertices</source>
        <translation>%1 kleine Löcher mit %2 neuen Vertices gefüllt</translation>
    </message>
    <message>
        <source>the mesh is open (%1 borders, the longest of %2 edges)</source>
        <translation>das Netz ist offen (%1 Ränder, der längste mit %2 Kanten)</translation>
    </message>
    <message>
        <source>the mesh is %1 separate pieces</source>
        <translation>das Netz besteht aus %1 getrennten Stücken</translation>
    </message>
    <message>
        <source>%1 pairs of the mesh&apos;s faces cross each other</source>
        <translation>%1 Flächenpaare des Netzes kreuzen sich</translation>
    </message>
    <message>
        <source>the mesh is not a manifold (more than two faces meet at an edge)</source>
        <translation>das Netz ist keine Mannigfaltigkeit (mehr als zwei Flächen treffen sich an einer Kante)</translation>
    </message>
    <message>
        <source>A vertex of the mesh is not a finite number: the file is corrupt.</source>
        <translation>Ein Vertex des Netzes ist keine endliche Zahl: die Datei ist beschädigt.</translation>
    </message>
    <message>
        <source>A face of the mesh names vertex %1, but the mesh has only %2 vertices: the file is corrupt.</source>
        <translation>Eine Fläche des Netzes nennt Vertex %1, das Netz hat aber nur %2 Vertices: die Datei ist beschädigt.</translation>
    </message>
    <message>
        <source>The mesh has %1 faces: rigging it would need more than the %2 MiB of memory allowed. Decimate it in your modelling tool (in Blender: the Decimate modifier) and import it again.</source>
        <translation>Das Netz hat %1 Flächen: es zu riggen bräuchte mehr als die erlaubten %2 MiB Speicher. Dezimieren Sie es (in Blender: der Modifikator Decimate) und importieren Sie es erneut.</translation>
    </message>
    <message>
        <source>the skeleton and weights were computed on a closed proxy of %1 vertices wrapped around the mesh&apos;s %2 pieces; the mesh itself is kept as it was</source>
        <translation>Skelett und Gewichte wurden auf einer geschlossenen Hülle aus %1 Vertices berechnet, die die %2 Stücke des Netzes umschließt; das Netz selbst bleibt, wie es war</translation>
    </message>
    <message>
        <source>%1 small pieces (eyes, teeth, buttons) follow bone %2</source>
        <translation>%1 kleine Stücke (Augen, Zähne, Knöpfe) folgen dem Knochen %2</translation>
    </message>
    <message>
        <source>%1 more small pieces follow one bone each</source>
        <translation>%1 weitere kleine Stücke folgen je einem Knochen</translation>
    </message>
    <message>
        <source>the mesh has %1 vertices, too many to compute the skeleton on directly</source>
        <translation>das Netz hat %1 Vertices, zu viele, um das Skelett direkt darauf zu berechnen</translation>
    </message>
    <message>
        <source>the mesh&apos;s edges are long for its size (on average %1% of its diagonal), too coarse to compute the skeleton on directly</source>
        <translation>die Kanten des Netzes sind für seine Größe lang (im Mittel %1% seiner Diagonale), zu grob, um das Skelett direkt darauf zu berechnen</translation>
    </message>
    <message>
        <source>%1 pieces of the proxy lie apart from the body and follow its nearest bones</source>
        <translation>%1 Stücke der Hülle liegen abseits des Körpers und folgen seinen nächsten Knochen</translation>
    </message>
    <message>
        <source>Bone %1 is not connected to its parent; connect it first (Edit &gt; Connect Bone).</source>
        <translation>Knochen %1 ist nicht mit seinem Elternknochen verbunden; verbinden Sie ihn zuerst (Bearbeiten &gt; Knochen verbinden).</translation>
    </message>
    <message>
        <source>Bone %1 is already connected to its parent.</source>
        <translation>Knochen %1 ist bereits mit seinem Elternknochen verbunden.</translation>
    </message>
    <message>
        <source>Bone %1 starts at the skeleton&apos;s root: it has no parent to connect to.</source>
        <translation>Knochen %1 beginnt an der Wurzel des Skeletts: Er hat keinen Elternknochen, mit dem er verbunden werden könnte.</translation>
    </message>
    <message>
        <source>The surface would intersect itself (%1 crossing face pairs) near (%2, %3): the outline is too thin or turns too sharply there. Widen it there or use a smaller edge length.</source>
        <translation>Die Oberfläche würde sich selbst schneiden (%1 kreuzende Flächenpaare) bei (%2, %3): der Umriss ist dort zu dünn oder zu spitz. Verbreitern Sie ihn oder nehmen Sie kleinere Kanten.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; cannot be rebuilt: it was not drawn as one sketch (it comes from a merge, a cut, a bone edit or an import), so there is no stroke to build it from.</source>
        <translation>„%1“ lässt sich nicht neu aufbauen: es wurde nicht als eine Skizze gezeichnet (es entstand durch Zusammenführen, Schneiden, Knochenbearbeitung oder Import) und hat keinen Strich.</translation>
    </message>
    <message>
        <source>The target part cannot be merged: %1 Merging needs closed, consistently oriented surfaces.</source>
        <translation>Das Zielteil lässt sich nicht zusammenführen: %1 Zusammenführen braucht geschlossene, einheitlich orientierte Oberflächen.</translation>
    </message>
    <message>
        <source>The dragged part cannot be merged: %1 Merging needs closed, consistently oriented surfaces.</source>
        <translation>Das gezogene Teil lässt sich nicht zusammenführen: %1 Zusammenführen braucht geschlossene, einheitlich orientierte Oberflächen.</translation>
    </message>
    <message>
        <source>The target part&apos;s surface intersects itself (%1 crossing face pairs), so the parts cannot be merged. Rebuild it with a larger edge length or smoothing first.</source>
        <translation>Die Oberfläche des Zielteils schneidet sich selbst (%1 kreuzende Flächenpaare), daher lassen sich die Teile nicht zusammenführen. Bauen Sie es mit größerer Kantenlänge oder Glättung neu.</translation>
    </message>
    <message>
        <source>The dragged part&apos;s surface intersects itself (%1 crossing face pairs), so the parts cannot be merged. Rebuild it with a larger edge length or smoothing first.</source>
        <translation>Die Oberfläche des gezogenen Teils schneidet sich selbst (%1 kreuzende Flächenpaare), daher lassen sich die Teile nicht zusammenführen. Bauen Sie es mit größerer Kantenlänge oder Glättung neu.</translation>
    </message>
    <message>
        <source>The joints to connect are %1 apart, less than the shortest bone allowed (%2); snap them instead.</source>
        <translation>Die zu verbindenden Gelenke liegen %1 auseinander, weniger als der kürzeste erlaubte Knochen (%2); fügen Sie sie stattdessen zusammen.</translation>
    </message>
    <message>
        <source>The part cannot be cut: %1 Cutting needs a closed, consistently oriented surface.</source>
        <translation>Das Teil lässt sich nicht schneiden: %1 Schneiden braucht eine geschlossene, einheitlich orientierte Oberfläche.</translation>
    </message>
    <message>
        <source>The cut would leave a piece without a bone: its only one would be %1 long, shorter than the shortest bone allowed (%2). Cut farther from the joint.</source>
        <translation>Der Schnitt ließe ein Stück ohne Knochen zurück: sein einziger wäre %1 lang, kürzer als der kürzeste erlaubte Knochen (%2). Schneiden Sie weiter vom Gelenk entfernt.</translation>
    </message>
    <message>
        <source>Splitting there would leave a bone %1 long, shorter than the shortest bone allowed (%2); split nearer the bone&apos;s middle.</source>
        <translation>Eine Teilung dort ließe einen Knochen von %1 Länge zurück, kürzer als der kürzeste erlaubte Knochen (%2); teilen Sie näher an der Mitte des Knochens.</translation>
    </message>
    <message>
        <source>Deleting the bone would leave bone %1 only %2 long, shorter than the shortest bone allowed (%3); delete a neighbouring bone instead.</source>
        <translation>Das Löschen des Knochens ließe Knochen %1 nur %2 lang zurück, kürzer als der kürzeste erlaubte Knochen (%3); löschen Sie stattdessen einen benachbarten Knochen.</translation>
    </message>
    <message>
        <source>A key time must be a finite number of seconds.</source>
        <translation>Die Zeit eines Schlüsselbilds muss eine endliche Anzahl von Sekunden sein.</translation>
    </message>
    <message>
        <source>A key at %1 s is out of range: keys lie at 0 s or later.</source>
        <translation>Ein Schlüsselbild bei %1 s liegt außerhalb des Bereichs: Schlüsselbilder liegen bei 0 s oder später.</translation>
    </message>
    <message>
        <source>A key at %1 s is out of range: keys lie from 0 s to %2 s.</source>
        <translation>Ein Schlüsselbild bei %1 s liegt außerhalb des Bereichs: Schlüsselbilder liegen zwischen 0 s und %2 s.</translation>
    </message>
    <message>
        <source>A clip&apos;s frame rate must be a positive number of frames per second.</source>
        <translation>Die Bildrate eines Clips muss eine positive Anzahl Bilder pro Sekunde sein.</translation>
    </message>
    <message>
        <source>The part has no bone %1 to lock.</source>
        <translation>Das Teil hat keinen Knochen %1 zum Sperren.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: there is no such file.</source>
        <translation>„%1“ kann nicht importiert werden: die Datei existiert nicht.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it is not a file.</source>
        <translation>„%1“ kann nicht importiert werden: es ist keine Datei.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the program that reads imports (rigmesh) is not installed.</source>
        <translation>„%1“ kann nicht importiert werden: das Programm, das Importe liest (rigmesh), ist nicht installiert.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the import reader could not be started (%2).</source>
        <translation>„%1“ kann nicht importiert werden: das Importprogramm konnte nicht gestartet werden (%2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: reading it took longer than %2 s, so it was stopped (the file is probably broken).</source>
        <translation>„%1“ kann nicht importiert werden: das Lesen dauerte länger als %2 s und wurde abgebrochen (die Datei ist wahrscheinlich beschädigt).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer crashed on it (%2); the file is probably broken.</source>
        <translation>„%1“ kann nicht importiert werden: das Importprogramm ist daran abgestürzt (%2); die Datei ist wahrscheinlich beschädigt.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: reading it needed more than %2 of memory, so it was stopped.</source>
        <translation>„%1“ kann nicht importiert werden: das Lesen brauchte mehr als %2 Speicher und wurde abgebrochen.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer failed (exit status %2).</source>
        <translation>„%1“ kann nicht importiert werden: das Importprogramm ist gescheitert (Exit-Status %2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the importer returned bad data (%2).</source>
        <translation>„%1“ kann nicht importiert werden: das Importprogramm lieferte fehlerhafte Daten (%2).</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: its part &quot;%2&quot; is not usable: %3</source>
        <translation>„%1“ kann nicht importiert werden: sein Teil „%2“ ist nicht verwendbar: %3</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: %2</source>
        <translation>„%1“ kann nicht importiert werden: %2</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it is damaged or not in a format the importer knows.</source>
        <translation>„%1“ kann nicht importiert werden: die Datei ist beschädigt oder in einem Format, das das Importprogramm nicht kennt.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: the file is incomplete.</source>
        <translation>„%1“ kann nicht importiert werden: die Datei ist unvollständig.</translation>
    </message>
    <message>
        <source>Cannot import &quot;%1&quot;: it holds no triangle mesh.</source>
        <translation>„%1“ kann nicht importiert werden: sie enthält kein Dreiecksnetz.</translation>
    </message>
    <message>
        <source>The mesh is too small for a bone: its only bone would be %1 long, shorter than the shortest bone allowed (%2).</source>
        <translation>Das Netz ist zu klein für einen Knochen: sein einziger Knochen wäre %1 lang, kürzer als der kürzeste erlaubte Knochen (%2).</translation>
    </message>
    <message>
        <source>This part has no left-right mirror plane (its two sides differ by more than 2% of its size), so X-mirror cannot paint it.</source>
        <translation>Dieses Teil hat keine Links-rechts-Spiegelebene (seine beiden Seiten weichen um mehr als 2 % seiner Größe voneinander ab), daher kann X-Spiegelung es nicht malen.</translation>
    </message>
    <message>
        <source>No part with id %1 in the document.</source>
        <translation>Im Dokument gibt es kein Teil mit der Kennung %1.</translation>
    </message>
    <message>
        <source>Part %1 has no joint %2.</source>
        <translation>Teil %1 hat kein Gelenk %2.</translation>
    </message>
    <message>
        <source>The pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>Die Pose von Teil %1 hat eine nicht endliche oder null Rotation oder Verschiebung.</translation>
    </message>
    <message>
        <source>The key at %1 s of part %2 has a non-finite or zero rotation or translation.</source>
        <translation>Das Schlüsselbild bei %1 s von Teil %2 hat eine nicht endliche oder null Rotation oder Verschiebung.</translation>
    </message>
    <message>
        <source>The starting pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>Die Ausgangspose von Teil %1 hat eine nicht endliche oder null Rotation oder Verschiebung.</translation>
    </message>
    <message>
        <source>The new pose of part %1 has a non-finite or zero rotation or translation.</source>
        <translation>Die neue Pose von Teil %1 hat eine nicht endliche oder null Rotation oder Verschiebung.</translation>
    </message>
    <message>
        <source>The starting pose names joint %1, which part %2 does not have.</source>
        <translation>Die Ausgangspose nennt Gelenk %1, das Teil %2 nicht hat.</translation>
    </message>
    <message>
        <source>The new pose names joint %1, which part %2 does not have.</source>
        <translation>Die neue Pose nennt Gelenk %1, das Teil %2 nicht hat.</translation>
    </message>
    <message>
        <source>The part has no skeleton to pose.</source>
        <translation>Das Teil hat kein Skelett zum Posieren.</translation>
    </message>
    <message>
        <source>The part has no skeleton to edit.</source>
        <translation>Das Teil hat kein Skelett zum Bearbeiten.</translation>
    </message>
    <message>
        <source>The part has no surface to cut.</source>
        <translation>Das Teil hat keine Oberfläche zum Schneiden.</translation>
    </message>
    <message>
        <source>The cut&apos;s view needs a direction and an up that is not along it.</source>
        <translation>Die Ansicht des Schnitts braucht eine Richtung und ein Oben, das nicht entlang dieser Richtung liegt.</translation>
    </message>
    <message>
        <source>A part cannot be merged into itself.</source>
        <translation>Ein Teil lässt sich nicht mit sich selbst zusammenführen.</translation>
    </message>
    <message>
        <source>%1 has no joint %2</source>
        <translation>%1 hat kein Gelenk %2</translation>
    </message>
    <message>
        <source>The parts to merge are no longer in the document.</source>
        <translation>Die zusammenzuführenden Teile sind nicht mehr im Dokument.</translation>
    </message>
    <message>
        <source>There is no such part.</source>
        <translation>Dieses Teil gibt es nicht.</translation>
    </message>
    <message>
        <source>The part is no longer in the document.</source>
        <translation>Das Teil ist nicht mehr im Dokument.</translation>
    </message>
    <message>
        <source>There is no part to rig.</source>
        <translation>Es gibt kein Teil zum Riggen.</translation>
    </message>
    <message>
        <source>The part changed while it was rigged; nothing was changed.</source>
        <translation>Das Teil hat sich während des Riggens geändert; nichts wurde geändert.</translation>
    </message>
    <message>
        <source>The parts to rig together must be given in document order, once each.</source>
        <translation>Die gemeinsam zu riggenden Teile müssen in Dokumentreihenfolge und je einmal angegeben werden.</translation>
    </message>
    <message>
        <source>There is no part to recompute the weights of.</source>
        <translation>Es gibt kein Teil, dessen Gewichte neu berechnet werden könnten.</translation>
    </message>
    <message>
        <source>The part changed while its weights were recomputed; nothing was changed.</source>
        <translation>Das Teil hat sich während der Neuberechnung seiner Gewichte geändert; nichts wurde geändert.</translation>
    </message>
    <message>
        <source>%1 holds no mesh to import</source>
        <translation>%1 enthält kein Netz zum Importieren</translation>
    </message>
    <message>
        <source>there are no parts to export</source>
        <translation>es gibt keine Teile zum Exportieren</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not rigged yet: export it as OBJ, or hide it and export the visible parts</source>
        <translation>„%1“ ist noch nicht geriggt: exportieren Sie es als OBJ oder blenden Sie es aus und exportieren Sie die sichtbaren Teile</translation>
    </message>
    <message>
        <source>The history step &quot;%1&quot; cannot be written as a recipe step.</source>
        <translation>Der Verlaufsschritt „%1“ lässt sich nicht als Rezeptschritt schreiben.</translation>
    </message>
    <message>
        <source>lists and maps are nested more than %1 levels deep</source>
        <translation>Listen und Maps sind mehr als %1 Ebenen tief verschachtelt</translation>
    </message>
    <message>
        <source>The frame rate must be between %1 and %2 frames per second.</source>
        <translation>Die Bildrate muss zwischen %1 und %2 Bildern pro Sekunde liegen.</translation>
    </message>
    <message>
        <source>The frame range must lie within frames 0 to %1.</source>
        <translation>Der Bildbereich muss zwischen den Bildern 0 und %1 liegen.</translation>
    </message>
    <message>
        <source>The frame range must end after it starts.</source>
        <translation>Der Bildbereich muss nach seinem Anfang enden.</translation>
    </message>
    <message>
        <source>The frame range is longer than a clip can be.</source>
        <translation>Der Bildbereich ist länger, als ein Clip sein kann.</translation>
    </message>
    <message>
        <source>Frame %1 is outside frames 0 to %2.</source>
        <translation>Bild %1 liegt außerhalb der Bilder 0 bis %2.</translation>
    </message>
    <message>
        <source>A clip name must have 1 to %1 characters.</source>
        <translation>Ein Clipname muss 1 bis %1 Zeichen haben.</translation>
    </message>
    <message>
        <source>A clip name must not start or end with a space.</source>
        <translation>Ein Clipname darf nicht mit einem Leerzeichen beginnen oder enden.</translation>
    </message>
    <message>
        <source>A clip name must not hold control characters.</source>
        <translation>Ein Clipname darf keine Steuerzeichen enthalten.</translation>
    </message>
    <message>
        <source>The part has two clips named &quot;%1&quot;.</source>
        <translation>Das Teil hat zwei Clips namens „%1“.</translation>
    </message>
    <message>
        <source>%1 already has a clip named &quot;%2&quot;.</source>
        <translation>%1 hat bereits einen Clip namens „%2“.</translation>
    </message>
    <message>
        <source>%1 has no clip named &quot;%2&quot;.</source>
        <translation>%1 hat keinen Clip namens „%2“.</translation>
    </message>
    <message>
        <source>%1 has only this clip: a part keeps one clip (delete its keys instead).</source>
        <translation>%1 hat nur diesen Clip: ein Teil behält einen Clip (löschen Sie stattdessen seine Schlüsselbilder).</translation>
    </message>
    <message>
        <source>There are no keys to paste.</source>
        <translation>Es gibt keine Schlüsselbilder zum Einfügen.</translation>
    </message>
    <message>
        <source>There are no keys to move.</source>
        <translation>Es gibt keine Schlüsselbilder zum Verschieben.</translation>
    </message>
    <message>
        <source>The keys&apos; offset is not a finite number of seconds.</source>
        <translation>Der Versatz der Schlüsselbilder ist keine endliche Anzahl von Sekunden.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to paint.</source>
        <translation>Das Teil hat kein Skelett und damit keine Gewichte zum Malen.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to lock.</source>
        <translation>Das Teil hat kein Skelett und damit keine Gewichte zum Sperren.</translation>
    </message>
    <message>
        <source>The part has no skeleton, so it has no weights to clean up.</source>
        <translation>Das Teil hat kein Skelett und damit keine Gewichte zum Bereinigen.</translation>
    </message>
    <message>
        <source>Only a part with a skeleton has weights to recompute.</source>
        <translation>Nur ein Teil mit Skelett hat Gewichte, die sich neu berechnen lassen.</translation>
    </message>
    <message>
        <source>Check Rig needs at least one influence and a positive tolerance.</source>
        <translation>Rig prüfen braucht mindestens einen Einfluss und eine positive Toleranz.</translation>
    </message>
    <message>
        <source>A skin weight refers to bone %1, which the skeleton does not have.</source>
        <translation>Ein Skin-Gewicht verweist auf Knochen %1, den das Skelett nicht hat.</translation>
    </message>
    <message>
        <source>Skin weights need at least one bone.</source>
        <translation>Skin-Gewichte brauchen mindestens einen Knochen.</translation>
    </message>
    <message>
        <source>Skin weights need at least one bone with finite end points.</source>
        <translation>Skin-Gewichte brauchen mindestens einen Knochen mit endlichen Endpunkten.</translation>
    </message>
    <message>
        <source>The mesh has a vertex with a non-finite position.</source>
        <translation>Das Netz hat einen Vertex mit nicht endlicher Position.</translation>
    </message>
    <message>
        <source>The mesh has a triangle that refers to a missing vertex.</source>
        <translation>Das Netz hat ein Dreieck, das auf einen fehlenden Vertex verweist.</translation>
    </message>
    <message>
        <source>A bone cannot connect joint %1 to itself.</source>
        <translation>Ein Knochen kann Gelenk %1 nicht mit sich selbst verbinden.</translation>
    </message>
    <message>
        <source>Only existing joints can be merged.</source>
        <translation>Nur vorhandene Gelenke lassen sich zusammenführen.</translation>
    </message>
    <message>
        <source>The root joint %1 cannot hang from a bone.</source>
        <translation>Das Wurzelgelenk %1 kann nicht an einem Knochen hängen.</translation>
    </message>
    <message>
        <source>The skeleton has no bone %1.</source>
        <translation>Das Skelett hat keinen Knochen %1.</translation>
    </message>
    <message>
        <source>Cannot choose a root for a skeleton without joints.</source>
        <translation>Für ein Skelett ohne Gelenke lässt sich keine Wurzel wählen.</translation>
    </message>
    <message>
        <source>the skeleton of this shape is invalid: %1</source>
        <translation>das Skelett dieser Form ist ungültig: %1</translation>
    </message>
    <message>
        <source>subdividing &apos;%1&apos; failed: %2</source>
        <translation>Unterteilen von „%1“ ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>decimating &apos;%1&apos; failed: %2</source>
        <translation>Dezimieren von „%1“ ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <source>the pose demo needs a part with bones</source>
        <translation>die Posen-Demo braucht ein Teil mit Knochen</translation>
    </message>
    <message>
        <source>the outline has no elongated part to inflate: draw a longer shape</source>
        <translation>die Umrisslinie hat keinen länglichen Teil zum Aufblasen: zeichnen Sie eine längere Form</translation>
    </message>
    <message>
        <source>a patch boundary needs at least three points</source>
        <translation>ein Flächenrand braucht mindestens drei Punkte</translation>
    </message>
    <message>
        <source>the target edge length must be positive</source>
        <translation>die Ziel-Kantenlänge muss positiv sein</translation>
    </message>
    <message>
        <source>the edge length is too small for this patch: %1 lattice rows or columns</source>
        <translation>die Kantenlänge ist für diese Fläche zu klein: %1 Gitterzeilen oder -spalten</translation>
    </message>
    <message>
        <source>the edge length is too small for this patch: %1 lattice points</source>
        <translation>die Kantenlänge ist für diese Fläche zu klein: %1 Gitterpunkte</translation>
    </message>
    <message>
        <source>least-squares smoothing needs at least one anchored vertex</source>
        <translation>die Glättung nach kleinsten Quadraten braucht mindestens einen verankerten Vertex</translation>
    </message>
    <message>
        <source>The target edge length must be 0 (automatic) or a positive length.</source>
        <translation>Die Ziel-Kantenlänge muss 0 (automatisch) oder eine positive Länge sein.</translation>
    </message>
    <message>
        <source>Cannot open &apos;%1&apos;: the file does not exist or is not readable.</source>
        <translation>„%1“ lässt sich nicht öffnen: die Datei existiert nicht oder ist nicht lesbar.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: reading the file failed.</source>
        <translation>„%1“ lässt sich nicht lesen: das Lesen der Datei ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>Unsupported mesh file type &apos;%1&apos;: use .obj, .off or .ply.</source>
        <translation>Nicht unterstützter Netz-Dateityp „%1“: verwenden Sie .obj, .off oder .ply.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a vertex needs three coordinates.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: ein Vertex braucht drei Koordinaten.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a face needs at least three vertices.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: eine Fläche braucht mindestens drei Vertices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: face refers to vertex %3 but only %4 vertices are defined before it.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: die Fläche verweist auf Vertex %3, aber davor sind nur %4 Vertices definiert.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: &apos;%3&apos; is not a finite number.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: „%3“ ist keine endliche Zahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: &apos;%3&apos; is not an integer.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: „%3“ ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: invalid count &apos;%3&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: ungültige Anzahl „%3“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting the OFF header.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei endet zu früh, statt des OFF-Kopfes.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting the vertex and face counts.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei endet zu früh, statt der Vertex- und Flächenanzahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting vertex %2 of %3.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei endet zu früh, statt Vertex %2 von %3.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file ends early, while expecting face %2 of %3.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei endet zu früh, statt Fläche %2 von %3.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file does not start with &apos;OFF&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei beginnt nicht mit „OFF“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: expected the vertex and face counts.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: erwartet wurden die Vertex- und Flächenanzahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: a face needs a corner count of at least 3 and that many vertex indices.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: eine Fläche braucht eine Eckenzahl von mindestens 3 und so viele Vertex-Indizes.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: line %2: face refers to vertex %3 but there are %4 vertices.</source>
        <translation>„%1“ lässt sich nicht lesen: Zeile %2: die Fläche verweist auf Vertex %3, es gibt aber %4 Vertices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file does not start with &apos;ply&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei beginnt nicht mit „ply“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the header has no &apos;end_header&apos; line.</source>
        <translation>„%1“ lässt sich nicht lesen: der Kopf hat keine Zeile „end_header“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the header has no &apos;format&apos; line.</source>
        <translation>„%1“ lässt sich nicht lesen: der Kopf hat keine Zeile „format“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unknown property type &apos;%3&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: unbekannter Eigenschaftstyp „%3“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unknown format &apos;%3&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: unbekanntes Format „%3“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: &apos;%3&apos; is not an integer.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: „%3“ ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: invalid element count &apos;%3&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: ungültige Elementanzahl „%3“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: a list count must have an integer type.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: eine Listenlänge muss einen ganzzahligen Typ haben.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: malformed property line.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: fehlerhafte Eigenschaftszeile.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: header line %2: unexpected &apos;%3&apos;.</source>
        <translation>„%1“ lässt sich nicht lesen: Kopfzeile %2: unerwartetes „%3“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file is truncated: it ends in %2 %3 of %4.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei ist abgeschnitten: sie endet in %2 %3 von %4.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: &apos;%5&apos; is not a finite number.</source>
        <translation>„%1“ lässt sich nicht lesen: %2 %3 von %4: „%5“ ist keine endliche Zahl.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: list length is %5, outside [0, %6).</source>
        <translation>„%1“ lässt sich nicht lesen: %2 %3 von %4: die Listenlänge ist %5, außerhalb von [0, %6).</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: vertex index is %5, outside [0, %6).</source>
        <translation>„%1“ lässt sich nicht lesen: %2 %3 von %4: der Vertex-Index ist %5, außerhalb von [0, %6).</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: a face needs at least three vertices.</source>
        <translation>„%1“ lässt sich nicht lesen: %2 %3 von %4: eine Fläche braucht mindestens drei Vertices.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: %2 %3 of %4: a coordinate is not finite.</source>
        <translation>„%1“ lässt sich nicht lesen: %2 %3 von %4: eine Koordinate ist nicht endlich.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the vertex element lacks an x, y or z property.</source>
        <translation>„%1“ lässt sich nicht lesen: dem Vertex-Element fehlt eine Eigenschaft x, y oder z.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file has more than one vertex element.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei hat mehr als ein Vertex-Element.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the face element lacks a &apos;vertex_indices&apos; list.</source>
        <translation>„%1“ lässt sich nicht lesen: dem Flächen-Element fehlt eine Liste „vertex_indices“.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file is truncated: element &apos;%2&apos; declares %3 entries that do not fit.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei ist abgeschnitten: Element „%2“ gibt %3 Einträge an, die nicht hineinpassen.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: the file has no vertex element.</source>
        <translation>„%1“ lässt sich nicht lesen: die Datei hat kein Vertex-Element.</translation>
    </message>
    <message>
        <source>Cannot read &apos;%1&apos;: face %2 refers to vertex %3 but there are %4 vertices.</source>
        <translation>„%1“ lässt sich nicht lesen: Fläche %2 verweist auf Vertex %3, es gibt aber %4 Vertices.</translation>
    </message>
    <message>
        <source>Cannot write the mesh: vertex %1 is not a finite point.</source>
        <translation>Das Netz lässt sich nicht schreiben: Vertex %1 ist kein endlicher Punkt.</translation>
    </message>
    <message>
        <source>Cannot write the mesh: face %1 refers to vertex %2 but there are only %3 vertices.</source>
        <translation>Das Netz lässt sich nicht schreiben: Fläche %1 verweist auf Vertex %2, es gibt aber nur %3 Vertices.</translation>
    </message>
    <message>
        <source>The mesh has a vertex with a non-finite coordinate.</source>
        <translation>Das Netz hat einen Vertex mit nicht endlicher Koordinate.</translation>
    </message>
    <message>
        <source>Face %1 refers to vertex %2 but the mesh has %3 vertices.</source>
        <translation>Fläche %1 verweist auf Vertex %2, das Netz hat aber %3 Vertices.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: point %2 has %3 as its %4 coordinate; every coordinate must be a number.</source>
        <translation>Skizze „%1“: Punkt %2 hat %3 als %4-Koordinate; jede Koordinate muss eine Zahl sein.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not valid JSON: %2</source>
        <translation>Skizze „%1“ ist kein gültiges JSON: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; has a number out of range: %2</source>
        <translation>Skizze „%1“ hat eine Zahl außerhalb des Wertebereichs: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; must be a JSON object with a &quot;points&quot; array of [x, y] pairs.</source>
        <translation>Skizze „%1“ muss ein JSON-Objekt mit einem Array „points“ aus [x, y]-Paaren sein.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; has no &quot;points&quot; array of [x, y] pairs.</source>
        <translation>Skizze „%1“ hat kein Array „points“ aus [x, y]-Paaren.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: point %2 is not an [x, y] pair of numbers.</source>
        <translation>Skizze „%1“: Punkt %2 ist kein [x, y]-Zahlenpaar.</translation>
    </message>
    <message>
        <source>Cannot read sketch &quot;%1&quot;: unknown file type &quot;%2&quot;; use a .json or .svg file.</source>
        <translation>Skizze „%1“ lässt sich nicht lesen: unbekannter Dateityp „%2“; verwenden Sie eine .json- oder .svg-Datei.</translation>
    </message>
    <message>
        <source>Cannot read sketch file &quot;%1&quot;: it does not exist or is not readable.</source>
        <translation>Skizzendatei „%1“ lässt sich nicht lesen: sie existiert nicht oder ist nicht lesbar.</translation>
    </message>
    <message>
        <source>Cannot read sketch file &quot;%1&quot;: reading it failed.</source>
        <translation>Skizzendatei „%1“ lässt sich nicht lesen: das Lesen ist fehlgeschlagen.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not valid SVG: %2</source>
        <translation>Skizze „%1“ ist kein gültiges SVG: %2</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; is not an SVG document (no &lt;svg&gt; root element).</source>
        <translation>Skizze „%1“ ist kein SVG-Dokument (kein Wurzelelement &lt;svg&gt;).</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot; contains no path, polyline or polygon to use as the stroke.</source>
        <translation>Skizze „%1“ enthält keinen Pfad, keine Polylinie und kein Polygon als Strich.</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote invalid JSON</source>
        <translation>Export nicht möglich: der glTF-Exporter hat ungültiges JSON geschrieben</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote an unknown component type</source>
        <translation>Export nicht möglich: der glTF-Exporter hat einen unbekannten Komponententyp geschrieben</translation>
    </message>
    <message>
        <source>cannot export: a glTF accessor lies outside its buffer</source>
        <translation>Export nicht möglich: ein glTF-Accessor liegt außerhalb seines Puffers</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote a buffer view out of range</source>
        <translation>Export nicht möglich: der glTF-Exporter hat eine Pufferansicht außerhalb des Bereichs geschrieben</translation>
    </message>
    <message>
        <source>cannot export: the glTF exporter wrote no buffer</source>
        <translation>Export nicht möglich: der glTF-Exporter hat keinen Puffer geschrieben</translation>
    </message>
    <message>
        <source>cannot export: the COLLADA exporter wrote invalid XML</source>
        <translation>Export nicht möglich: der COLLADA-Exporter hat ungültiges XML geschrieben</translation>
    </message>
    <message>
        <source>cannot export an animation of nothing</source>
        <translation>eine Animation von nichts lässt sich nicht exportieren</translation>
    </message>
    <message>
        <source>cannot export an animation without keys</source>
        <translation>eine Animation ohne Schlüsselbilder lässt sich nicht exportieren</translation>
    </message>
    <message>
        <source>cannot export the animation: no node %1</source>
        <translation>die Animation lässt sich nicht exportieren: kein Knoten %1</translation>
    </message>
    <message>
        <source>cannot export: the unit scale must be positive</source>
        <translation>Export nicht möglich: der Einheitenmaßstab muss positiv sein</translation>
    </message>
    <message>
        <source>cannot export %1: unknown format &apos;%2&apos;; use .glb, .gltf, .fbx, .dae or .obj</source>
        <translation>%1 lässt sich nicht exportieren: unbekanntes Format „%2“; verwenden Sie .glb, .gltf, .fbx, .dae oder .obj</translation>
    </message>
    <message>
        <source>part &apos;%1&apos; has no skeleton to export</source>
        <translation>Teil „%1“ hat kein Skelett zum Exportieren</translation>
    </message>
    <message>
        <source>cannot write the rig: vertex %1 is not at a finite position</source>
        <translation>das Rig lässt sich nicht schreiben: Vertex %1 liegt nicht an einer endlichen Position</translation>
    </message>
    <message>
        <source>cannot write the rig: joint %1 is not at a finite position</source>
        <translation>das Rig lässt sich nicht schreiben: Gelenk %1 liegt nicht an einer endlichen Position</translation>
    </message>
    <message>
        <source>cannot write the rig: a weight of vertex %1 is not finite</source>
        <translation>das Rig lässt sich nicht schreiben: ein Gewicht von Vertex %1 ist nicht endlich</translation>
    </message>
    <message>
        <source>there is no part at index %1 (the document has %2 part)</source>
        <translation>es gibt kein Teil mit Index %1 (das Dokument hat %2 Teil)</translation>
    </message>
    <message>
        <source>there is no part at index %1 (the document has %2 parts)</source>
        <translation>es gibt kein Teil mit Index %1 (das Dokument hat %2 Teile)</translation>
    </message>
    <message>
        <source>&quot;part&quot; must be a part&apos;s name or its index (from 0)</source>
        <translation>„part“ muss der Name eines Teils oder sein Index (ab 0) sein</translation>
    </message>
    <message>
        <source>there is no part &quot;%1&quot;</source>
        <translation>es gibt kein Teil „%1“</translation>
    </message>
    <message>
        <source>%1 parts are named &quot;%2&quot;; refer to the part by its index</source>
        <translation>%1 Teile heißen „%2“; verweisen Sie auf das Teil über seinen Index</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no bone %2</source>
        <translation>Teil „%1“ hat keinen Knochen %2</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no joint %2</source>
        <translation>Teil „%1“ hat kein Gelenk %2</translation>
    </message>
    <message>
        <source>part &quot;%1&quot; has no skeleton</source>
        <translation>Teil „%1“ hat kein Skelett</translation>
    </message>
    <message>
        <source>&quot;mode&quot; must be &quot;add&quot;, &quot;subtract&quot;, &quot;replace&quot; or &quot;smooth&quot;</source>
        <translation>„mode“ muss „add“, „subtract“, „replace“ oder „smooth“ sein</translation>
    </message>
    <message>
        <source>&quot;falloff&quot; must be &quot;smooth&quot;, &quot;linear&quot;, &quot;sharp&quot; or &quot;constant&quot;</source>
        <translation>„falloff“ muss „smooth“, „linear“, „sharp“ oder „constant“ sein</translation>
    </message>
    <message>
        <source>&quot;locked&quot; must be a list of bone ids</source>
        <translation>„locked“ muss eine Liste von Knochen-IDs sein</translation>
    </message>
    <message>
        <source>a dab needs &quot;center&quot; and &quot;radius&quot;</source>
        <translation>ein Tupfer braucht „center“ und „radius“</translation>
    </message>
    <message>
        <source>the step needs &quot;center&quot; and &quot;radius&quot;</source>
        <translation>der Schritt braucht „center“ und „radius“</translation>
    </message>
    <message>
        <source>the step needs either &quot;center&quot; and &quot;radius&quot; or &quot;dabs&quot;</source>
        <translation>der Schritt braucht entweder „center“ und „radius“ oder „dabs“</translation>
    </message>
    <message>
        <source>&quot;dabs&quot; must be a non-empty list of {&quot;center&quot;, &quot;radius&quot;}</source>
        <translation>„dabs“ muss eine nicht leere Liste von {&quot;center&quot;, &quot;radius&quot;} sein</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole number from %2 to %3</source>
        <translation>„%1“ muss eine ganze Zahl von %2 bis %3 sein</translation>
    </message>
    <message>
        <source>the step needs &quot;%1&quot;</source>
        <translation>der Schritt braucht „%1“</translation>
    </message>
    <message>
        <source>the step needs either &quot;stroke&quot; (a sketch file) or &quot;points&quot;, not both</source>
        <translation>der Schritt braucht entweder „stroke“ (eine Skizzendatei) oder „points“, nicht beides</translation>
    </message>
    <message>
        <source>the step needs either &quot;joint&quot; and &quot;target&quot; (an IK drag) or &quot;rotations&quot;</source>
        <translation>der Schritt braucht entweder „joint“ und „target“ (ein IK-Ziehen) oder „rotations“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; goes with &quot;rotations&quot;, not &quot;target&quot;</source>
        <translation>„%1“ gehört zu „rotations“, nicht zu „target“</translation>
    </message>
    <message>
        <source>&quot;reach&quot; must be &quot;limb&quot; or &quot;body&quot;</source>
        <translation>„reach“ muss „limb“ oder „body“ sein</translation>
    </message>
    <message>
        <source>&quot;reach&quot; goes with &quot;target&quot; (an IK drag), not &quot;rotations&quot;</source>
        <translation>„reach“ gehört zu „target“ (ein IK-Ziehen), nicht zu „rotations“</translation>
    </message>
    <message>
        <source>&quot;interpolation&quot; must be &quot;constant&quot;, &quot;linear&quot; or &quot;smooth&quot;</source>
        <translation>„interpolation“ muss „constant“, „linear“ oder „smooth“ sein</translation>
    </message>
    <message>
        <source>&quot;playback&quot; must be &quot;hold&quot;, &quot;loop&quot; or &quot;ping_pong&quot;</source>
        <translation>„playback“ muss „hold“, „loop“ oder „ping_pong“ sein</translation>
    </message>
    <message>
        <source>&quot;times&quot; must be a list of seconds</source>
        <translation>„times“ muss eine Liste von Sekunden sein</translation>
    </message>
    <message>
        <source>&quot;keys&quot; must be a list of keys</source>
        <translation>„keys“ muss eine Liste von Schlüsselbildern sein</translation>
    </message>
    <message>
        <source>each key needs &quot;time&quot; and &quot;rotations&quot;</source>
        <translation>jedes Schlüsselbild braucht „time“ und „rotations“</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole frame</source>
        <translation>„%1“ muss ein ganzes Bild sein</translation>
    </message>
    <message>
        <source>&quot;mode&quot; must be &quot;snap&quot;, &quot;split&quot; or &quot;connect&quot;</source>
        <translation>„mode“ muss „snap“, „split“ oder „connect“ sein</translation>
    </message>
    <message>
        <source>&quot;reskin&quot; must be &quot;local&quot; or &quot;global&quot;</source>
        <translation>„reskin“ muss „local“ oder „global“ sein</translation>
    </message>
    <message>
        <source>the step needs either &quot;plane&quot; or &quot;stroke&quot; with &quot;view&quot;</source>
        <translation>der Schritt braucht entweder „plane“ oder „stroke“ mit „view“</translation>
    </message>
    <message>
        <source>&quot;plane&quot; needs &quot;point&quot; and &quot;normal&quot;</source>
        <translation>„plane“ braucht „point“ und „normal“</translation>
    </message>
    <message>
        <source>&quot;view&quot; needs &quot;direction&quot; and &quot;up&quot;</source>
        <translation>„view“ braucht „direction“ und „up“</translation>
    </message>
    <message>
        <source>the cut needs a stroke of two points or more</source>
        <translation>der Schnitt braucht einen Strich aus zwei oder mehr Punkten</translation>
    </message>
    <message>
        <source>&quot;style&quot; must be &quot;smooth&quot; or &quot;sharp&quot;</source>
        <translation>„style“ muss „smooth“ oder „sharp“ sein</translation>
    </message>
    <message>
        <source>&quot;names&quot; must be two names</source>
        <translation>„names“ muss aus zwei Namen bestehen</translation>
    </message>
    <message>
        <source>&quot;parts&quot; must be a non-empty list of parts, without &quot;part&quot;</source>
        <translation>„parts“ muss eine nicht leere Liste von Teilen sein, ohne „part“</translation>
    </message>
    <message>
        <source>unknown command &quot;%1&quot;</source>
        <translation>unbekannter Befehl „%1“</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot;</source>
        <translation>unbekanntes Feld „%1“</translation>
    </message>
    <message>
        <source>this is not a RigMesh recipe (it needs &quot;format&quot;: &quot;%1&quot;)</source>
        <translation>dies ist kein RigMesh-Rezept (es braucht &quot;format&quot;: &quot;%1&quot;)</translation>
    </message>
    <message>
        <source>the recipe has no valid &quot;version&quot;</source>
        <translation>das Rezept hat keine gültige „version“</translation>
    </message>
    <message>
        <source>the recipe is of version %1; this RigMesh Studio reads recipes of version %2 and older</source>
        <translation>das Rezept hat Version %1; dieses RigMesh Studio liest Rezepte bis Version %2</translation>
    </message>
    <message>
        <source>the recipe has no list of &quot;steps&quot;</source>
        <translation>das Rezept hat keine Liste „steps“</translation>
    </message>
    <message>
        <source>%1 is not valid JSON: %2</source>
        <translation>%1 ist kein gültiges JSON: %2</translation>
    </message>
    <message>
        <source>%1 has a number out of range: %2</source>
        <translation>%1 hat eine Zahl außerhalb des Wertebereichs: %2</translation>
    </message>
    <message>
        <source>cannot read the recipe %1</source>
        <translation>das Rezept %1 lässt sich nicht lesen</translation>
    </message>
    <message>
        <source>cannot write %1: the folder does not exist or is read-only</source>
        <translation>%1 kann nicht geschrieben werden: der Ordner existiert nicht oder ist schreibgeschützt</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>&quot;edgeLength&quot; must be 0 (automatic) or a positive length</source>
        <translation>„edgeLength“ muss 0 (automatisch) oder eine positive Länge sein</translation>
    </message>
    <message>
        <source>&quot;points&quot; must be a list of [x, y] points</source>
        <translation>„points“ muss eine Liste von [x, y]-Punkten sein</translation>
    </message>
    <message>
        <source>&quot;rotations&quot; must be an object {&quot;&lt;joint id&gt;&quot;: [w, x, y, z], ...}</source>
        <translation>„rotations“ muss ein Objekt {&quot;&lt;joint id&gt;&quot;: [w, x, y, z], ...} sein</translation>
    </message>
    <message>
        <source>&quot;rotations&quot; names joint %1 twice</source>
        <translation>„rotations“ nennt Gelenk %1 zweimal</translation>
    </message>
    <message>
        <source>The surface of the part is not a manifold.</source>
        <translation>Die Oberfläche des Teils ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface of the part has a hole, so it does not bound a volume.</source>
        <translation>Die Oberfläche des Teils hat ein Loch und umschließt daher kein Volumen.</translation>
    </message>
    <message>
        <source>The surface of the cut is not a manifold.</source>
        <translation>Die Oberfläche des Schnitts ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface of the target part is not a manifold.</source>
        <translation>Die Oberfläche des Zielteils ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface of the target part has a hole, so it does not bound a volume.</source>
        <translation>Die Oberfläche des Zielteils hat ein Loch und umschließt daher kein Volumen.</translation>
    </message>
    <message>
        <source>The surface of the dragged part is not a manifold.</source>
        <translation>Die Oberfläche des gezogenen Teils ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface of the dragged part has a hole, so it does not bound a volume.</source>
        <translation>Die Oberfläche des gezogenen Teils hat ein Loch und umschließt daher kein Volumen.</translation>
    </message>
    <message>
        <source>The surface of the mesh is not a manifold.</source>
        <translation>Die Oberfläche des Netzes ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface of the mesh has a hole, so it does not bound a volume.</source>
        <translation>Die Oberfläche des Netzes hat ein Loch und umschließt daher kein Volumen.</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: not a binary FBX file</source>
        <translation>die FBX-Datei lässt sich nicht reparieren: keine binäre FBX-Datei</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: no node records</source>
        <translation>die FBX-Datei lässt sich nicht reparieren: keine Knoteneinträge</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: a record runs past the end of the file</source>
        <translation>die FBX-Datei lässt sich nicht reparieren: ein Eintrag reicht über das Dateiende hinaus</translation>
    </message>
    <message>
        <source>cannot repair the FBX file: a nested record is out of range</source>
        <translation>die FBX-Datei lässt sich nicht reparieren: ein verschachtelter Eintrag liegt außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>cannot export: vertex %1 of mesh &apos;%2&apos; is not a finite number</source>
        <translation>Export nicht möglich: Vertex %1 von Netz „%2“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: the normal of vertex %1 of mesh &apos;%2&apos; is not a finite number</source>
        <translation>Export nicht möglich: die Normale von Vertex %1 von Netz „%2“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: the bind matrix of bone &apos;%1&apos; is not a finite number</source>
        <translation>Export nicht möglich: die Bindungsmatrix von Knochen „%1“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: a weight of bone &apos;%1&apos; is not a finite number</source>
        <translation>Export nicht möglich: ein Gewicht von Knochen „%1“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: the transform of node &apos;%1&apos; is not a finite number</source>
        <translation>Export nicht möglich: die Transformation von Knoten „%1“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: a key of &apos;%1&apos; is not a finite number</source>
        <translation>Export nicht möglich: ein Schlüsselbild von „%1“ ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>cannot export: the animation&apos;s duration is not a finite number</source>
        <translation>Export nicht möglich: die Dauer der Animation ist keine endliche Zahl</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the flow gave no curve.</source>
        <translation>Im Netz ließ sich kein Skelett finden: der Fluss ergab keine Kurve.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the curve is too short for a bone.</source>
        <translation>Im Netz ließ sich kein Skelett finden: die Kurve ist für einen Knochen zu kurz.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the flow contracted it to a point.</source>
        <translation>Im Netz ließ sich kein Skelett finden: der Fluss hat es auf einen Punkt zusammengezogen.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the mesh has too few vertices.</source>
        <translation>Im Netz ließ sich kein Skelett finden: das Netz hat zu wenige Vertices.</translation>
    </message>
    <message>
        <source>No skeleton could be found in the mesh: the mesh has no extent.</source>
        <translation>Im Netz ließ sich kein Skelett finden: das Netz hat keine Ausdehnung.</translation>
    </message>
    <message>
        <source>cannot write %1: the glTF exporter wrote no .bin</source>
        <translation>%1 kann nicht geschrieben werden: der glTF-Exporter hat keine .bin geschrieben</translation>
    </message>
    <message>
        <source>Skin weights could not be solved for bone %1; nearest-bone weights are used instead.</source>
        <translation>Die Skin-Gewichte für Knochen %1 ließen sich nicht lösen; stattdessen werden Gewichte des nächsten Knochens verwendet.</translation>
    </message>
    <message>
        <source>Skin weights could not be solved for bones %1; nearest-bone weights are used instead.</source>
        <translation>Die Skin-Gewichte für die Knochen %1 ließen sich nicht lösen; stattdessen werden Gewichte des nächsten Knochens verwendet.</translation>
    </message>
    <message>
        <source>The skin weights&apos; heat system could not be factored; every bone uses nearest-bone weights instead.</source>
        <translation>Das Wärmesystem der Skin-Gewichte ließ sich nicht faktorisieren; jeder Knochen verwendet stattdessen Gewichte des nächsten Knochens.</translation>
    </message>
    <message>
        <source>%1 vertices see no bone from inside the shape and are heated by their nearest bone.</source>
        <translation>%1 Vertices sehen von innerhalb der Form keinen Knochen und werden vom nächsten Knochen erwärmt.</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a letter in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Buchstabe erwartet in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a name in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Name erwartet in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected a number in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Zahl erwartet in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: number out of range in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Zahl außerhalb des Bereichs in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected an arc flag (0 or 1) in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Bogen-Flag (0 oder 1) erwartet in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: path data must start with a moveto command (M or m) in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: Pfaddaten müssen mit einem Moveto-Befehl (M oder m) beginnen, in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: unknown command &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: unbekannter Befehl „%5“ in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: odd number of coordinates in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: ungerade Anzahl von Koordinaten in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: unknown transform &apos;%5&apos; with %6 arguments in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: unbekannte Transformation „%5“ mit %6 Argumenten in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: expected &apos;(&apos; after &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: „(“ erwartet nach „%5“ in „%4“</translation>
    </message>
    <message>
        <source>Sketch &quot;%1&quot;: the SVG attribute &quot;%2&quot; is malformed at character %3: missing &apos;)&apos; after &apos;%5&apos; in &quot;%4&quot;</source>
        <translation>Skizze „%1“: das SVG-Attribut „%2“ ist an Zeichen %3 fehlerhaft: „)“ fehlt nach „%5“ in „%4“</translation>
    </message>
    <message>
        <source>%1 must be a list of %2 numbers</source>
        <translation>%1 muss eine Liste von %2 Zahlen sein</translation>
    </message>
    <message>
        <source>%1 must be a list of 4 numbers [w, x, y, z]</source>
        <translation>%1 muss eine Liste von 4 Zahlen [w, x, y, z] sein</translation>
    </message>
    <message>
        <source>%1 must be an object</source>
        <translation>%1 muss ein Objekt sein</translation>
    </message>
    <message>
        <source>%1 has an unknown field &quot;%2&quot;</source>
        <translation>%1 hat ein unbekanntes Feld „%2“</translation>
    </message>
    <message>
        <source>%1 must be a number</source>
        <translation>%1 muss eine Zahl sein</translation>
    </message>
    <message>
        <source>%1 must be a finite number</source>
        <translation>%1 muss eine endliche Zahl sein</translation>
    </message>
    <message>
        <source>%1 must be true or false</source>
        <translation>%1 muss true oder false sein</translation>
    </message>
    <message>
        <source>%1 must be text</source>
        <translation>%1 muss Text sein</translation>
    </message>
    <message>
        <source>%1 is a zero quaternion</source>
        <translation>%1 ist ein Null-Quaternion</translation>
    </message>
    <message>
        <source>%1 is not a joint id</source>
        <translation>%1 ist keine Gelenk-ID</translation>
    </message>
    <message>
        <source>%1 must be a joint id (a non-negative integer)</source>
        <translation>%1 muss eine Gelenk-ID sein (eine nichtnegative ganze Zahl)</translation>
    </message>
    <message>
        <source>%1</source>
        <translation>%1</translation>
    </message>
    <message>
        <source>expected a map holding %1</source>
        <translation>erwartet wurde eine Zuordnung mit %1</translation>
    </message>
    <message>
        <source>missing %1</source>
        <translation>%1 fehlt</translation>
    </message>
    <message>
        <source>%1 is not a list</source>
        <translation>%1 ist keine Liste</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 ist keine Zahl</translation>
    </message>
    <message>
        <source>%1 holds a value that is not finite</source>
        <translation>%1 enthält einen Wert, der nicht endlich ist</translation>
    </message>
    <message>
        <source>%1 is not true or false</source>
        <translation>%1 ist weder true noch false</translation>
    </message>
    <message>
        <source>%1 is not text</source>
        <translation>%1 ist kein Text</translation>
    </message>
    <message>
        <source>%1 has the wrong length</source>
        <translation>%1 hat die falsche Länge</translation>
    </message>
    <message>
        <source>%1 is not an integer</source>
        <translation>%1 ist keine ganze Zahl</translation>
    </message>
    <message>
        <source>%1 is out of range</source>
        <translation>%1 liegt außerhalb des gültigen Bereichs</translation>
    </message>
    <message>
        <source>it ends too early, at byte %1</source>
        <translation>es endet zu früh, bei Byte %1</translation>
    </message>
    <message>
        <source>it is malformed at byte %1</source>
        <translation>es ist bei Byte %1 fehlerhaft</translation>
    </message>
    <message>
        <source>it holds a number too large to read</source>
        <translation>es enthält eine Zahl, die zu groß zum Lesen ist</translation>
    </message>
    <message>
        <source>a value has the wrong type</source>
        <translation>ein Wert hat den falschen Typ</translation>
    </message>
    <message>
        <source>it is malformed</source>
        <translation>es ist fehlerhaft</translation>
    </message>
    <message>
        <source>unknown weights warning %1</source>
        <translation>unbekannter Gewichtshinweis %1</translation>
    </message>
    <message>
        <source>weights warning %1 has the wrong number of arguments</source>
        <translation>Gewichtshinweis %1 hat die falsche Anzahl an Argumenten</translation>
    </message>
    <message>
        <source>%1 refers to a missing bone</source>
        <translation>%1 verweist auf einen fehlenden Knochen</translation>
    </message>
    <message>
        <source>%1 refers to bone %2, which the skeleton does not have</source>
        <translation>%1 verweist auf Knochen %2, den das Skelett nicht hat</translation>
    </message>
    <message>
        <source>%1 does not have one entry per vertex</source>
        <translation>%1 hat nicht genau einen Eintrag pro Vertex</translation>
    </message>
    <message>
        <source>%1 has a malformed entry</source>
        <translation>%1 hat einen fehlerhaften Eintrag</translation>
    </message>
    <message>
        <source>%1 holds a negative value</source>
        <translation>%1 enthält einen negativen Wert</translation>
    </message>
    <message>
        <source>the skin weights of vertex %1 sum to %2 instead of 1</source>
        <translation>die Skin-Gewichte von Vertex %1 ergeben zusammen %2 statt 1</translation>
    </message>
    <message>
        <source>joint ids and positions differ in number</source>
        <translation>Gelenk-IDs und Gelenkpositionen unterscheiden sich in der Anzahl</translation>
    </message>
    <message>
        <source>duplicate or invalid joint id</source>
        <translation>doppelte oder ungültige Gelenk-ID</translation>
    </message>
    <message>
        <source>bone ids, heads and tails differ in number</source>
        <translation>Knochen-IDs, -Köpfe und -Enden unterscheiden sich in der Anzahl</translation>
    </message>
    <message>
        <source>duplicate bone id</source>
        <translation>doppelte Knochen-ID</translation>
    </message>
    <message>
        <source>a bone refers to a missing joint</source>
        <translation>ein Knochen verweist auf ein fehlendes Gelenk</translation>
    </message>
    <message>
        <source>the skeleton root is not one of its joints</source>
        <translation>die Wurzel des Skeletts ist keines seiner Gelenke</translation>
    </message>
    <message>
        <source>attached joints and their bones differ in number</source>
        <translation>angehängte Gelenke und ihre Knochen unterscheiden sich in der Anzahl</translation>
    </message>
    <message>
        <source>an attachment refers to a missing joint or bone, or twice to one joint</source>
        <translation>eine Anhängung verweist auf ein fehlendes Gelenk oder einen fehlenden Knochen oder zweimal auf ein Gelenk</translation>
    </message>
    <message>
        <source>the skeleton is not a tree: %1</source>
        <translation>das Skelett ist kein Baum: %1</translation>
    </message>
    <message>
        <source>a face refers to a missing vertex</source>
        <translation>eine Fläche verweist auf einen fehlenden Vertex</translation>
    </message>
    <message>
        <source>unknown vertex origin kind</source>
        <translation>unbekannte Art der Vertex-Herkunft</translation>
    </message>
    <message>
        <source>the mirror map refers to a missing vertex</source>
        <translation>die Spiegelzuordnung verweist auf einen fehlenden Vertex</translation>
    </message>
    <message>
        <source>a rigged part needs skin weights for every vertex</source>
        <translation>ein geriggtes Teil braucht Skin-Gewichte für jeden Vertex</translation>
    </message>
    <message>
        <source>a bone name is not [bone id, name]</source>
        <translation>ein Knochenname ist nicht [Knochen-ID, Name]</translation>
    </message>
    <message>
        <source>a bone name refers to a missing bone, or twice to one</source>
        <translation>ein Knochenname verweist auf einen fehlenden Knochen oder zweimal auf einen</translation>
    </message>
    <message>
        <source>a locked bone refers to a missing bone, or twice to one</source>
        <translation>ein gesperrter Knochen verweist auf einen fehlenden Knochen oder zweimal auf einen</translation>
    </message>
    <message>
        <source>a bone frame is not [bone id, w, x, y, z]</source>
        <translation>ein Knochenrahmen ist nicht [Knochen-ID, w, x, y, z]</translation>
    </message>
    <message>
        <source>a bone frame is not a unit rotation of a bone, or names one twice</source>
        <translation>ein Knochenrahmen ist keine Einheitsdrehung eines Knochens oder nennt einen zweimal</translation>
    </message>
    <message>
        <source>the part fails its own check: %1</source>
        <translation>das Teil besteht seine eigene Prüfung nicht: %1</translation>
    </message>
    <message>
        <source>step %1 (%2): %3</source>
        <translation>Schritt %1 (%2): %3</translation>
    </message>
    <message>
        <source>a step must be an object {&quot;command&quot;: ..., ...}</source>
        <translation>ein Schritt muss ein Objekt {&quot;command&quot;: ..., ...} sein</translation>
    </message>
    <message>
        <source>the step has no &quot;command&quot;</source>
        <translation>der Schritt hat kein &quot;command&quot;</translation>
    </message>
    <message>
        <source>&quot;command&quot; must be text</source>
        <translation>&quot;command&quot; muss Text sein</translation>
    </message>
    <message>
        <source>Vertex %1 has a non-finite position.</source>
        <translation>Vertex %1 hat eine nicht endliche Position.</translation>
    </message>
    <message>
        <source>Face %1 refers to a missing vertex.</source>
        <translation>Fläche %1 verweist auf einen fehlenden Vertex.</translation>
    </message>
    <message>
        <source>Face %1 repeats a vertex.</source>
        <translation>Fläche %1 wiederholt einen Vertex.</translation>
    </message>
    <message>
        <source>The outline has a non-finite point.</source>
        <translation>Der Umriss hat einen nicht endlichen Punkt.</translation>
    </message>
    <message>
        <source>The vertex origins do not have one entry per vertex.</source>
        <translation>Die Vertex-Herkünfte haben nicht genau einen Eintrag pro Vertex.</translation>
    </message>
    <message>
        <source>The mirror map does not have one entry per vertex.</source>
        <translation>Die Spiegelzuordnung hat nicht genau einen Eintrag pro Vertex.</translation>
    </message>
    <message>
        <source>The mirror map refers to a missing vertex.</source>
        <translation>Die Spiegelzuordnung verweist auf einen fehlenden Vertex.</translation>
    </message>
    <message>
        <source>The skin weights do not have one entry per vertex.</source>
        <translation>Die Skin-Gewichte haben nicht genau einen Eintrag pro Vertex.</translation>
    </message>
    <message>
        <source>The skin weights have %1 entries for %2 vertices.</source>
        <translation>Die Skin-Gewichte haben %1 Einträge für %2 Vertices.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 name bone %2, which the skeleton does not have.</source>
        <translation>Die Skin-Gewichte von Vertex %1 nennen Knochen %2, den das Skelett nicht hat.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 are not in bone order.</source>
        <translation>Die Skin-Gewichte von Vertex %1 sind nicht nach Knochen geordnet.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 hold a value that is not finite and positive.</source>
        <translation>Die Skin-Gewichte von Vertex %1 enthalten einen Wert, der nicht endlich und positiv ist.</translation>
    </message>
    <message>
        <source>The skin weights of vertex %1 sum to %2, not 1.</source>
        <translation>Die Skin-Gewichte von Vertex %1 ergeben zusammen %2, nicht 1.</translation>
    </message>
    <message>
        <source>The known closest bones have %1 entries for %2 vertices.</source>
        <translation>Die bekannten nächsten Knochen haben %1 Einträge für %2 Vertices.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 name bone %2, which the skeleton does not have.</source>
        <translation>Die bekannten nächsten Knochen von Vertex %1 nennen Knochen %2, den das Skelett nicht hat.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 are not in bone order.</source>
        <translation>Die bekannten nächsten Knochen von Vertex %1 sind nicht nach Knochen geordnet.</translation>
    </message>
    <message>
        <source>The known closest bones of vertex %1 hold a value that is not finite and positive.</source>
        <translation>Die bekannten nächsten Knochen von Vertex %1 enthalten einen Wert, der nicht endlich und positiv ist.</translation>
    </message>
    <message>
        <source>The skeleton has bones but no joints.</source>
        <translation>Das Skelett hat Knochen, aber keine Gelenke.</translation>
    </message>
    <message>
        <source>An unrigged part has skin weights.</source>
        <translation>Ein Teil ohne Rig hat Skin-Gewichte.</translation>
    </message>
    <message>
        <source>The failed bones name a missing bone.</source>
        <translation>Die fehlgeschlagenen Knochen nennen einen fehlenden Knochen.</translation>
    </message>
    <message>
        <source>A bone name is empty, repeated or names a missing bone.</source>
        <translation>Ein Knochenname ist leer, doppelt oder nennt einen fehlenden Knochen.</translation>
    </message>
    <message>
        <source>Bone %1 is locked but the skeleton has no such bone.</source>
        <translation>Knochen %1 ist gesperrt, aber das Skelett hat keinen solchen Knochen.</translation>
    </message>
    <message>
        <source>A bone frame is not a unit rotation or names a missing bone.</source>
        <translation>Ein Knochenrahmen ist keine Einheitsdrehung oder nennt einen fehlenden Knochen.</translation>
    </message>
    <message>
        <source>The mesh pieces do not fit the mesh.</source>
        <translation>Die Netzstücke passen nicht zum Netz.</translation>
    </message>
    <message>
        <source>Mesh piece &apos;%1&apos; uses another piece&apos;s vertex.</source>
        <translation>Netzstück „%1“ benutzt einen Vertex eines anderen Stücks.</translation>
    </message>
    <message>
        <source>The mesh pieces do not cover the mesh.</source>
        <translation>Die Netzstücke decken das Netz nicht ab.</translation>
    </message>
    <message>
        <source>The surface has %1 boundary edges.</source>
        <translation>Die Oberfläche hat %1 Randkanten.</translation>
    </message>
    <message>
        <source>The surface is not a manifold.</source>
        <translation>Die Oberfläche ist keine Mannigfaltigkeit.</translation>
    </message>
    <message>
        <source>The surface is not consistently oriented.</source>
        <translation>Die Oberfläche ist nicht einheitlich orientiert.</translation>
    </message>
    <message>
        <source>The skeleton has no joints.</source>
        <translation>Das Skelett hat keine Gelenke.</translation>
    </message>
    <message>
        <source>Two joints share the id %1.</source>
        <translation>Zwei Gelenke teilen sich die ID %1.</translation>
    </message>
    <message>
        <source>Joint %1 has a non-finite position.</source>
        <translation>Gelenk %1 hat eine nicht endliche Position.</translation>
    </message>
    <message>
        <source>Two bones share the id %1.</source>
        <translation>Zwei Knochen teilen sich die ID %1.</translation>
    </message>
    <message>
        <source>The skeleton has no root joint.</source>
        <translation>Das Skelett hat kein Wurzelgelenk.</translation>
    </message>
    <message>
        <source>The root is joint %1, which does not exist.</source>
        <translation>Die Wurzel ist Gelenk %1, das es nicht gibt.</translation>
    </message>
    <message>
        <source>Bone %1 refers to joint %2, which does not exist.</source>
        <translation>Knochen %1 verweist auf Gelenk %2, das es nicht gibt.</translation>
    </message>
    <message>
        <source>Bone %1 connects joint %2 to itself.</source>
        <translation>Knochen %1 verbindet Gelenk %2 mit sich selbst.</translation>
    </message>
    <message>
        <source>Bone %1 has zero length.</source>
        <translation>Knochen %1 hat die Länge null.</translation>
    </message>
    <message>
        <source>The skeleton has a cycle: bone %1 closes a loop.</source>
        <translation>Das Skelett hat einen Zyklus: Knochen %1 schließt eine Schleife.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone but does not exist.</source>
        <translation>Gelenk %1 hängt an einem Knochen, existiert aber nicht.</translation>
    </message>
    <message>
        <source>The root joint %1 hangs from a bone.</source>
        <translation>Das Wurzelgelenk %1 hängt an einem Knochen.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from bone %2, which does not exist.</source>
        <translation>Gelenk %1 hängt an Knochen %2, den es nicht gibt.</translation>
    </message>
    <message>
        <source>Joints %1 and %2 both hang from bones but are in one chain.</source>
        <translation>Die Gelenke %1 und %2 hängen beide an Knochen, liegen aber in einer Kette.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone but is connected to the root&apos;s chain.</source>
        <translation>Gelenk %1 hängt an einem Knochen, ist aber mit der Kette der Wurzel verbunden.</translation>
    </message>
    <message>
        <source>The skeleton is not connected: it has %1 separate components.</source>
        <translation>Das Skelett ist nicht zusammenhängend: es hat %1 getrennte Teile.</translation>
    </message>
    <message>
        <source>The skeleton is not connected: it has %1 separate components, %2 of them hanging from no bone.</source>
        <translation>Das Skelett ist nicht zusammenhängend: es hat %1 getrennte Teile, %2 davon hängen an keinem Knochen.</translation>
    </message>
    <message>
        <source>Joint %1 hangs from a bone of its own chain.</source>
        <translation>Gelenk %1 hängt an einem Knochen seiner eigenen Kette.</translation>
    </message>
    <message>
        <source>The chain of joint %1 hangs from chains that hang from it.</source>
        <translation>Die Kette von Gelenk %1 hängt an Ketten, die an ihr hängen.</translation>
    </message>
    <message>
        <source>%1 props held in a hand (a handle through the fist) rigged as the arm&apos;s chain on to their far end</source>
        <translation>%1 in einer Hand gehaltene Gegenstände (ein Griff durch die Faust) als Kette des Arms bis zu ihrem fernen Ende geriggt</translation>
    </message>
    <message>
        <source>%1 pieces worn at a limb&apos;s end (horns on a helmet, a crest) ride on the limb&apos;s last bone</source>
        <translation>%1 am Ende einer Gliedmaße getragene Teile (Hörner am Helm, ein Kamm) folgen ihrem letzten Knochen</translation>
    </message>
</context>
<context>
    <name>ImportPartsCommand</name>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
</context>
<context>
    <name>KeyPoseCommand</name>
    <message>
        <source>Key %1 at %2 s</source>
        <translation>Schlüsselbild für %1 bei %2 s</translation>
    </message>
</context>
<context>
    <name>MergePartsCommand</name>
    <message>
        <source>Merge %1 into %2</source>
        <translation>%1 mit %2 zusammenführen</translation>
    </message>
    <message>
        <source>merged in %1 ms: %2 vertices, %3 bones; %4 vertices and %5 bones re-skinned</source>
        <translation>in %1 ms zusammengeführt: %2 Vertices, %3 Knochen; %4 Vertices und %5 Knochen neu gewichtet</translation>
    </message>
    <message numerus="yes">
        <source>; %n bone(s) pruned</source>
        <translation>
            <numerusform>; %n Knochen entfernt</numerusform>
            <numerusform>; %n Knochen entfernt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %1 lost the pose, pins and keys of %n pruned joint(s)</source>
        <translation>
            <numerusform>; %1 hat Pose, Fixierungen und Schlüsselbilder von %n entfernten Gelenk verloren</numerusform>
            <numerusform>; %1 hat Pose, Fixierungen und Schlüsselbilder von %n entfernten Gelenken verloren</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MoveKeyCommand</name>
    <message>
        <source>Move key of %1 from %2 s to %3 s</source>
        <translation>Schlüsselbild von %1 von %2 s nach %3 s verschieben</translation>
    </message>
</context>
<context>
    <name>MoveKeysCommand</name>
    <message numerus="yes">
        <source>Move %n key(s) of %1 by %2 s</source>
        <translation>
            <numerusform>%n Schlüsselbild von %1 um %2 s verschieben</numerusform>
            <numerusform>%n Schlüsselbilder von %1 um %2 s verschieben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MovePartCommand</name>
    <message>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message>
        <source>Rotate %1</source>
        <translation>%1 drehen</translation>
    </message>
</context>
<context>
    <name>PaintWeightsCommand</name>
    <message>
        <source>Paint Weights of %1</source>
        <translation>Gewichte von %1 malen</translation>
    </message>
</context>
<context>
    <name>PasteKeysCommand</name>
    <message numerus="yes">
        <source>Paste %n key(s) into %1</source>
        <translation>
            <numerusform>%n Schlüsselbild in %1 einfügen</numerusform>
            <numerusform>%n Schlüsselbilder in %1 einfügen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>the clip of &quot;%1&quot; is not exported: the current pose is the file&apos;s rest shape</source>
        <translation>der Clip von „%1“ wird nicht exportiert: die aktuelle Pose ist die Ruheform der Datei</translation>
    </message>
    <message>
        <source>the clip of &quot;%1&quot; is not exported: its current pose is the file&apos;s one key</source>
        <translation>der Clip von „%1“ wird nicht exportiert: seine aktuelle Pose ist das einzige Schlüsselbild der Datei</translation>
    </message>
    <message>
        <source>RigMesh documents (*.%1)</source>
        <translation>RigMesh-Dokumente (*.%1)</translation>
    </message>
</context>
<context>
    <name>RebuildPartCommand</name>
    <message>
        <source>Rebuild %1</source>
        <translation>%1 neu bauen</translation>
    </message>
    <message numerus="yes">
        <source>the pose, pins and keys of %n joint(s) were dropped: the new skeleton has no joint there</source>
        <translation>
            <numerusform>Pose, Fixierungen und Schlüsselbilder von %n Gelenk wurden verworfen: das neue Skelett hat dort kein Gelenk</numerusform>
            <numerusform>Pose, Fixierungen und Schlüsselbilder von %n Gelenken wurden verworfen: das neue Skelett hat dort keine Gelenke</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RenamePartCommand</name>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>ResetPoseCommand</name>
    <message>
        <source>Reset pose of %1</source>
        <translation>Pose von %1 zurücksetzen</translation>
    </message>
</context>
<context>
    <name>RigPartCommand</name>
    <message>
        <source>Rig %1</source>
        <translation>%1 riggen</translation>
    </message>
    <message numerus="yes">
        <source>%1 rigged with %n bone(s)</source>
        <translation>
            <numerusform>%1 mit %n Knochen geriggt</numerusform>
            <numerusform>%1 mit %n Knochen geriggt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex(es) saw no bone from inside and follow the closest one</source>
        <translation>
            <numerusform>; %n Vertex sah von innen keinen Knochen und folgt dem nächsten</numerusform>
            <numerusform>; %n Vertices sahen von innen keinen Knochen und folgen dem nächsten</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Rig %1 with %n more part(s)</source>
        <translation>
            <numerusform>%1 mit %n weiteren Teil riggen</numerusform>
            <numerusform>%1 mit %n weiteren Teilen riggen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 and %2 more parts rigged as one with %n bone(s)</source>
        <translation>
            <numerusform>%1 und %2 weitere Teile als eines mit %n Knochen geriggt</numerusform>
            <numerusform>%1 und %2 weitere Teile als eines mit %n Knochen geriggt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>SetBoneLockCommand</name>
    <message>
        <source>Lock Weights of %1 in %2</source>
        <translation>Gewichte von %1 in %2 sperren</translation>
    </message>
    <message>
        <source>Unlock Weights of %1 in %2</source>
        <translation>Gewichte von %1 in %2 entsperren</translation>
    </message>
</context>
<context>
    <name>SetClipSettingsCommand</name>
    <message>
        <source>Set clip of %1</source>
        <translation>Clip von %1 einstellen</translation>
    </message>
</context>
<context>
    <name>SetJointPinnedCommand</name>
    <message>
        <source>Pin %1</source>
        <translation>%1 fixieren</translation>
    </message>
    <message>
        <source>Unpin %1</source>
        <translation>Fixierung von %1 lösen</translation>
    </message>
</context>
<context>
    <name>SetPartVisibleCommand</name>
    <message>
        <source>Show %1</source>
        <translation>%1 einblenden</translation>
    </message>
    <message>
        <source>Hide %1</source>
        <translation>%1 ausblenden</translation>
    </message>
</context>
<context>
    <name>SetPoseCommand</name>
    <message>
        <source>Pose %1</source>
        <translation>%1 posieren</translation>
    </message>
</context>
<context>
    <name>SetTimelineCommand</name>
    <message>
        <source>Set the frame range to %1-%2 at %3 fps</source>
        <translation>Bildbereich auf %1–%2 bei %3 fps setzen</translation>
    </message>
</context>
<context>
    <name>WeightCleanupCommand</name>
    <message>
        <source>Normalize All Weights of %1</source>
        <translation>Alle Gewichte von %1 normalisieren</translation>
    </message>
    <message>
        <source>Clean Weights of %1</source>
        <translation>Gewichte von %1 bereinigen</translation>
    </message>
    <message>
        <source>Limit Total Weights of %1</source>
        <translation>Gesamtzahl der Gewichte von %1 begrenzen</translation>
    </message>
    <message>
        <source>Smooth All Weights of %1</source>
        <translation>Alle Gewichte von %1 glätten</translation>
    </message>
    <message>
        <source>Recompute Weights of %1</source>
        <translation>Gewichte von %1 neu berechnen</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::Autosave</name>
    <message>
        <source>Cannot create the recovery folder &quot;%1&quot;.</source>
        <translation>Der Wiederherstellungsordner „%1“ lässt sich nicht anlegen.</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::DocumentFile</name>
    <message>
        <source>This is not a RigMesh Studio document.</source>
        <translation>Dies ist kein RigMesh-Studio-Dokument.</translation>
    </message>
    <message>
        <source>This document was saved by a newer RigMesh Studio (format version %1); this version reads format version %2 and older. Please update RigMesh Studio.</source>
        <translation>Dieses Dokument wurde mit einem neueren RigMesh Studio gespeichert (Formatversion %1); diese Version liest Formatversion %2 und älter. Bitte aktualisieren Sie RigMesh Studio.</translation>
    </message>
    <message>
        <source>The file is empty.</source>
        <translation>Die Datei ist leer.</translation>
    </message>
    <message>
        <source>The document is corrupt or truncated (%1).</source>
        <translation>Das Dokument ist beschädigt oder abgeschnitten (%1).</translation>
    </message>
    <message>
        <source>Cannot save &quot;%1&quot;: %2</source>
        <translation>„%1“ kann nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Cannot open &quot;%1&quot;: %2</source>
        <translation>„%1“ kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>a pose rotation of %1 is not [joint, w, x, y, z]</source>
        <translation>eine Posendrehung von %1 ist nicht [Gelenk, w, x, y, z]</translation>
    </message>
    <message>
        <source>pose joint %1 of %2 is not a joint of its skeleton</source>
        <translation>Posengelenk %1 von %2 ist kein Gelenk seines Skeletts</translation>
    </message>
    <message>
        <source>the pose rotation of joint %1 of %2 is not finite or is zero</source>
        <translation>die Posendrehung von Gelenk %1 von %2 ist nicht endlich oder null</translation>
    </message>
    <message>
        <source>the pose of %1 rotates joint %2 twice</source>
        <translation>die Pose von %1 dreht Gelenk %2 zweimal</translation>
    </message>
    <message>
        <source>the pose root translation of %1 has the wrong length</source>
        <translation>die Wurzelverschiebung der Pose von %1 hat die falsche Länge</translation>
    </message>
    <message>
        <source>the pose root translation of %1 is not finite</source>
        <translation>die Wurzelverschiebung der Pose von %1 ist nicht endlich</translation>
    </message>
    <message>
        <source>the clip frame rate of %1 is not positive</source>
        <translation>die Bildrate des Clips von %1 ist nicht positiv</translation>
    </message>
    <message>
        <source>a key time of %1 is not finite</source>
        <translation>eine Keyzeit von %1 ist nicht endlich</translation>
    </message>
    <message>
        <source>the clip of %1 has two keys at one time</source>
        <translation>der Clip von %1 hat zwei Keys zur selben Zeit</translation>
    </message>
    <message>
        <source>unknown clip interpolation &quot;%1&quot;</source>
        <translation>unbekannte Clip-Interpolation „%1“</translation>
    </message>
    <message>
        <source>unknown clip playback &quot;%1&quot;</source>
        <translation>unbekannte Clip-Wiedergabe „%1“</translation>
    </message>
    <message>
        <source>the timeline: %1</source>
        <translation>die Zeitleiste: %1</translation>
    </message>
    <message>
        <source>pinned joint %1 of %2 is not a joint of its skeleton</source>
        <translation>angeheftetes Gelenk %1 von %2 ist kein Gelenk seines Skeletts</translation>
    </message>
    <message>
        <source>a joint of %1 is pinned twice</source>
        <translation>ein Gelenk von %1 ist zweimal angeheftet</translation>
    </message>
    <message>
        <source>a part has no id</source>
        <translation>ein Teil hat keine ID</translation>
    </message>
    <message>
        <source>a placement has the wrong length</source>
        <translation>eine Platzierung hat die falsche Länge</translation>
    </message>
    <message>
        <source>the placement rotation of part %1 is not a unit quaternion</source>
        <translation>die Platzierungsdrehung von Teil %1 ist keine Einheitsquaternion</translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation>Teil %1: %2</translation>
    </message>
    <message>
        <source>a part has no geometry</source>
        <translation>ein Teil hat keine Geometrie</translation>
    </message>
    <message>
        <source>invalid format version</source>
        <translation>ungültige Formatversion</translation>
    </message>
    <message>
        <source>two parts have the same id</source>
        <translation>zwei Teile haben dieselbe ID</translation>
    </message>
    <message>
        <source>the next part id is already in use</source>
        <translation>die nächste Teil-ID ist bereits vergeben</translation>
    </message>
    <message>
        <source>The document is corrupt: %1.</source>
        <translation>Das Dokument ist beschädigt: %1.</translation>
    </message>
    <message>
        <source>part %1 (&quot;%2&quot;)</source>
        <translation>Teil %1 („%2“)</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::PartNode</name>
    <message>
        <source>Joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::PoseChange</name>
    <message>
        <source>%1 and key</source>
        <translation>%1 und Schlüsselbild setzen</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::SceneItemModel</name>
    <message>
        <source>%1 vertices, %2 faces</source>
        <translation>%1 Vertices, %2 Flächen</translation>
    </message>
    <message>
        <source>Skeleton</source>
        <translation>Skelett</translation>
    </message>
    <message>
        <source>Joint %1 (root)</source>
        <translation>Gelenk %1 (Wurzel)</translation>
    </message>
    <message>
        <source>Joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message numerus="yes">
        <source>, bone %1: %n vertices</source>
        <translation>
            <numerusform>, Knochen %1: %n Vertex</numerusform>
            <numerusform>, Knochen %1: %n Vertices</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 (pinned)</source>
        <translation>%1 (fixiert)</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <source>1 joint</source>
        <translation>1 Gelenk</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 Gelenke</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 Knochen</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 Knochen</translation>
    </message>
</context>
<context>
    <name>rigmesh::model::TimelineEdits</name>
    <message numerus="yes">
        <source>Paste %n key(s)</source>
        <translation>
            <numerusform>%n Schlüsselbild einfügen</numerusform>
            <numerusform>%n Schlüsselbilder einfügen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::model::TimelineItemModel</name>
    <message>
        <source>%1: key at frame %2 (%3 s)</source>
        <translation>%1: Schlüsselbild bei Bild %2 (%3 s)</translation>
    </message>
    <message>
        <source>Frame %1: %2 s</source>
        <translation>Bild %1: %2 s</translation>
    </message>
</context>
<context>
    <name>rigmesh::studio</name>
    <message>
        <source>Example: %1</source>
        <translation>Beispiel: %1</translation>
    </message>
    <message>
        <source>Sketch a silhouette, get a rigged part.</source>
        <translation>Skizzieren Sie eine Silhouette und erhalten Sie ein geriggtes Teil.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE after start-up and quit.</source>
        <translation>Nach dem Start ein Bild des Fensters in DATEI speichern und beenden.</translation>
    </message>
    <message>
        <source>FILE</source>
        <translation>DATEI</translation>
    </message>
    <message>
        <source>RigMesh Studio</source>
        <translation>RigMesh Studio</translation>
    </message>
    <message>
        <source>Building the example</source>
        <translation>Das Beispiel wird erstellt</translation>
    </message>
    <message>
        <source>The example was not built: %1</source>
        <translation>Das Beispiel wurde nicht erstellt: %1</translation>
    </message>
    <message>
        <source>files</source>
        <translation>Dateien</translation>
    </message>
    <message>
        <source>RigMesh documents to open, or 3D files (glTF, FBX, OBJ, ...) to import</source>
        <translation>Zu öffnende RigMesh-Dokumente oder zu importierende 3D-Dateien (glTF, FBX, OBJ, ...)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::BusyBar</name>
    <message>
        <source>Working</source>
        <translation>In Arbeit</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::CommandLineFiles</name>
    <message>
        <source>Cannot open %1</source>
        <translation>%1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1 is not a file this user may read.</source>
        <translation>%1 ist keine Datei, die dieser Benutzer lesen darf.</translation>
    </message>
    <message>
        <source>%1 does not exist.</source>
        <translation>%1 existiert nicht.</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::CutTool</name>
    <message>
        <source>Cut: drag a line across a part, from outside it to outside it; release cuts it in two with a smooth face, Shift + release with a flat one; Esc cancels</source>
        <translation>Schneiden: ziehen Sie eine Linie quer über ein Teil, von außerhalb nach außerhalb; Loslassen schneidet es mit glatter Schnittfläche in zwei, Umschalt + Loslassen mit ebener; Esc bricht ab</translation>
    </message>
    <message>
        <source>Nothing cut: the line does not cross a part</source>
        <translation>Nichts geschnitten: die Linie kreuzt kein Teil</translation>
    </message>
    <message>
        <source>Nothing cut: draw the line across the whole part, from outside it to outside it</source>
        <translation>Nichts geschnitten: ziehen Sie die Linie quer über das ganze Teil, von außerhalb nach außerhalb</translation>
    </message>
    <message>
        <source>%1 in %2 ms (%3)</source>
        <translation>%1 in %2 ms (%3)</translation>
    </message>
    <message>
        <source>smooth face</source>
        <translation>glatte Schnittfläche</translation>
    </message>
    <message>
        <source>flat face</source>
        <translation>ebene Schnittfläche</translation>
    </message>
    <message>
        <source>Nothing cut: %1</source>
        <translation>Nichts geschnitten: %1</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Schneiden</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::DocumentView</name>
    <message>
        <source>Created %1</source>
        <translation>%1 erstellt</translation>
    </message>
    <message>
        <source>Nothing created: %1</source>
        <translation>Nichts erstellt: %1</translation>
    </message>
    <message>
        <source>Part %1</source>
        <translation>Teil %1</translation>
    </message>
    <message>
        <source>Building %1</source>
        <translation>%1 wird gebaut</translation>
    </message>
    <message>
        <source>Nothing created: the stroke crosses itself where the red cross is; draw a silhouette that does not cross itself</source>
        <translation>Nichts erstellt: Der Strich kreuzt sich beim roten Kreuz selbst; zeichnen Sie eine Silhouette, die sich nicht selbst kreuzt</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ExchangeController</name>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>3D scenes (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;All files (*)</source>
        <translation>3D-Szenen (*.glb *.gltf *.fbx *.dae *.obj *.ply *.off *.stl);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Importing %1</source>
        <translation>%1 wird importiert</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>Import nicht möglich</translation>
    </message>
    <message>
        <source>Import of %1 cancelled</source>
        <translation>Import von %1 abgebrochen</translation>
    </message>
    <message numerus="yes">
        <source>Imported %n part(s) from %1</source>
        <translation>
            <numerusform>%n Teil aus %1 importiert</numerusform>
            <numerusform>%n Teile aus %1 importiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>: %n of them without a skeleton, so they cannot be posed yet.</source>
        <translation>
            <numerusform>: %n davon ohne Skelett, es lässt sich also noch nicht posieren.</numerusform>
            <numerusform>: %n davon ohne Skelett, sie lassen sich also noch nicht posieren.</numerusform>
        </translation>
    </message>
    <message>
        <source>Save History as Recipe</source>
        <translation>Verlauf als Rezept speichern</translation>
    </message>
    <message>
        <source>RigMesh recipes (*.json)</source>
        <translation>RigMesh-Rezepte (*.json)</translation>
    </message>
    <message>
        <source>Saved the history as %1: replay it with rigmesh run</source>
        <translation>Verlauf als %1 gespeichert: mit „rigmesh run“ erneut abspielen</translation>
    </message>
    <message>
        <source>Cannot save the recipe</source>
        <translation>Rezept kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Nothing to export: sketch a part first</source>
        <translation>Nichts zu exportieren: skizzieren Sie zuerst ein Teil</translation>
    </message>
    <message>
        <source>Exporting %1</source>
        <translation>%1 wird exportiert</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <source>%1 could not be replaced: %2</source>
        <translation>%1 konnte nicht ersetzt werden: %2</translation>
    </message>
    <message>
        <source>no animation: no visible part has keys</source>
        <translation>keine Animation: kein sichtbares Teil hat Schlüsselbilder</translation>
    </message>
    <message>
        <source>Exported %1%2</source>
        <translation>%1%2 exportiert</translation>
    </message>
    <message>
        <source>Export of %1 cancelled: nothing written</source>
        <translation>Export von %1 abgebrochen: nichts geschrieben</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ExportDialog</name>
    <message>
        <source>glTF 2.0 binary (.glb)</source>
        <translation>glTF 2.0 binär (.glb)</translation>
    </message>
    <message>
        <source>glTF 2.0 (.gltf + .bin)</source>
        <translation>glTF 2.0 (.gltf + .bin)</translation>
    </message>
    <message>
        <source>FBX binary (.fbx)</source>
        <translation>FBX binär (.fbx)</translation>
    </message>
    <message>
        <source>COLLADA (.dae)</source>
        <translation>COLLADA (.dae)</translation>
    </message>
    <message>
        <source>Wavefront OBJ, static mesh (.obj)</source>
        <translation>Wavefront OBJ, statisches Netz (.obj)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Durchsuchen …</translation>
    </message>
    <message>
        <source>all the format allows</source>
        <translation>so viele das Format erlaubt</translation>
    </message>
    <message>
        <source>Bones per vertex; extra influences are cut and the rest renormalised</source>
        <translation>Knochen pro Vertex; überzählige Einflüsse werden entfernt und der Rest neu normalisiert</translation>
    </message>
    <message>
        <source>Rest pose</source>
        <translation>Ruheposition</translation>
    </message>
    <message>
        <source>Current pose as the rest shape</source>
        <translation>Aktuelle Pose als Ruheform</translation>
    </message>
    <message>
        <source>Current pose as one key</source>
        <translation>Aktuelle Pose als ein Schlüsselbild</translation>
    </message>
    <message>
        <source>As one key, the file keeps the rest shape and the skeleton opens in the current pose (an animation of a single key at 0 s)</source>
        <translation>Als ein Schlüsselbild behält die Datei die Ruheform, und das Skelett öffnet sich in der aktuellen Pose (eine Animation aus einem einzigen Schlüsselbild bei 0 s)</translation>
    </message>
    <message>
        <source>Animation (each part&apos;s keyed clip)</source>
        <translation>Animation (der Clip mit Schlüsselbildern jedes Teils)</translation>
    </message>
    <message>
        <source>Add leaf bones (an end bone at each leaf&apos;s tail)</source>
        <translation>Endknochen hinzufügen (ein Endknochen an jedem Blattende)</translation>
    </message>
    <message>
        <source>Like Blender&apos;s FBX option: importers then also know how long each leaf bone is (without, Blender gives a leaf its parent&apos;s length)</source>
        <translation>Wie die FBX-Option in Blender: Importprogramme kennen dann auch die Länge jedes Blattknochens (ohne sie gibt Blender einem Blattknochen die Länge seines Elternknochens)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Rounds of Loop subdivision: each makes four triangles of one; skin weights are carried</source>
        <translation>Durchgänge der Loop-Unterteilung: jeder macht aus einem Dreieck vier; die Skin-Gewichte werden übernommen</translation>
    </message>
    <message>
        <source>keep all</source>
        <translation>alle behalten</translation>
    </message>
    <message>
        <source> faces</source>
        <translation> Flächen</translation>
    </message>
    <message>
        <source>At most this many triangles per part (quadric error); every kept vertex keeps its weights</source>
        <translation>Höchstens so viele Dreiecke pro Teil (quadratischer Fehler); jeder erhaltene Vertex behält seine Gewichte</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Influences</source>
        <translation>Einflüsse</translation>
    </message>
    <message>
        <source>Subdivide</source>
        <translation>Unterteilen</translation>
    </message>
    <message>
        <source>Decimate to</source>
        <translation>Ausdünnen auf</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Pose</translation>
    </message>
    <message>
        <source>Export to</source>
        <translation>Exportieren nach</translation>
    </message>
    <message>
        <source>%1 (*.%2)</source>
        <translation>%1 (*.%2)</translation>
    </message>
    <message>
        <source>The file records dual quaternion skinning (Maya uses it); Blender skins it linearly unless Preserve Volume is on.</source>
        <translation>Die Datei vermerkt Dual-Quaternion-Skinning (Maya nutzt es); Blender skinnt sie linear, solange „Volumen erhalten“ aus ist.</translation>
    </message>
    <message>
        <source>The view bends with dual quaternions; this format is skinned linearly, so bent joints look different elsewhere.</source>
        <translation>Die Ansicht biegt mit Dual-Quaternionen; dieses Format wird linear geskinnt, gebogene Gelenke sehen anderswo also anders aus.</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::FilesController</name>
    <message>
        <source>Untitled %1</source>
        <translation>Unbenannt %1</translation>
    </message>
    <message>
        <source>Open Document</source>
        <translation>Dokument öffnen</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Cannot open document</source>
        <translation>Dokument kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Cannot save document</source>
        <translation>Dokument kann nicht gespeichert werden</translation>
    </message>
    <message>
        <source>Save Document</source>
        <translation>Dokument speichern</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them?</source>
        <translation>%1 hat ungespeicherte Änderungen. Speichern?</translation>
    </message>
    <message>
        <source>Recover unsaved work?</source>
        <translation>Ungespeicherte Arbeit wiederherstellen?</translation>
    </message>
    <message>
        <source>Could not recover: %1</source>
        <translation>Wiederherstellen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>RigMesh Studio did not close properly. Restore &quot;%1&quot;, autosaved %2?</source>
        <translation>RigMesh Studio wurde nicht ordnungsgemäß beendet. „%1“ wiederherstellen, automatisch gespeichert am %2?</translation>
    </message>
    <message>
        <source>%1 (recovered)</source>
        <translation>%1 (wiederhergestellt)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::HistoryView</name>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::JobStatus</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop waiting: the document stays as it was (Esc)</source>
        <translation>Nicht mehr warten: Das Dokument bleibt, wie es war (Esc)</translation>
    </message>
    <message>
        <source>%1… %2 s</source>
        <translation>%1 … %2 s</translation>
    </message>
    <message>
        <source>%1… %2% (%3 s)</source>
        <translation>%1… %2 % (%3 s)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::KeyDrag</name>
    <message numerus="yes">
        <source>Move keys by %n frame(s)</source>
        <translation>
            <numerusform>Schlüsselbilder um %n Bild verschieben</numerusform>
            <numerusform>Schlüsselbilder um %n Bilder verschieben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MainWindow</name>
    <message>
        <source>Ready: S sketches a part, Q selects, P poses; %1</source>
        <translation>Bereit: S skizziert ein Teil, Q wählt aus, P posiert; %1</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importieren …</translation>
    </message>
    <message>
        <source>&amp;Export...</source>
        <translation>&amp;Exportieren …</translation>
    </message>
    <message>
        <source>Save History as &amp;Recipe...</source>
        <translation>Verlauf als &amp;Rezept speichern …</translation>
    </message>
    <message>
        <source>&amp;Close</source>
        <translation>S&amp;chließen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Delete Part</source>
        <translation>Teil &amp;löschen</translation>
    </message>
    <message>
        <source>&amp;Preferences...</source>
        <translation>&amp;Einstellungen …</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>Frame &amp;All</source>
        <translation>&amp;Alles anzeigen</translation>
    </message>
    <message>
        <source>Frame &amp;Selected</source>
        <translation>Au&amp;swahl anzeigen</translation>
    </message>
    <message>
        <source>&amp;Wireframe</source>
        <translation>&amp;Drahtgitter</translation>
    </message>
    <message>
        <source>&amp;Dual Quaternion Skinning</source>
        <translation>&amp;Dual-Quaternion-Skinning</translation>
    </message>
    <message>
        <source>Off: linear blend skinning</source>
        <translation>Aus: lineares Blend-Skinning</translation>
    </message>
    <message>
        <source>Weights of the selected joint&apos;s bone: blue 0, green 0.5, red 1, dark blue none</source>
        <translation>Gewichte des Knochens am ausgewählten Gelenk: Blau 0, Grün 0,5, Rot 1, Dunkelblau keins</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Raster</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Select / Move</source>
        <translation>&amp;Auswählen / Verschieben</translation>
    </message>
    <message>
        <source>S&amp;ketch Part</source>
        <translation>Teil s&amp;kizzieren</translation>
    </message>
    <message>
        <source>&amp;Pose</source>
        <translation>&amp;Posieren</translation>
    </message>
    <message>
        <source>&amp;Merge Parts</source>
        <translation>Teile &amp;zusammenführen</translation>
    </message>
    <message>
        <source>&amp;Cut Part</source>
        <translation>Teil s&amp;chneiden</translation>
    </message>
    <message>
        <source>Paint &amp;Weights</source>
        <translation>&amp;Gewichte malen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Mouse Gestures</source>
        <translation>&amp;Mausgesten</translation>
    </message>
    <message>
        <source>&amp;About RigMesh Studio</source>
        <translation>Über RigMesh &amp;Studio</translation>
    </message>
    <message>
        <source>About RigMesh Studio</source>
        <translation>Über RigMesh Studio</translation>
    </message>
    <message>
        <source>&lt;b&gt;RigMesh Studio&lt;/b&gt;&lt;p&gt;Sketch a silhouette, get a rigged part: surface, skeleton and skin weights, after Borosán et al., &lt;i&gt;RigMesh&lt;/i&gt;, SIGGRAPH Asia 2012.&lt;/p&gt;&lt;p&gt;GPL-3.0-or-later.&lt;/p&gt;</source>
        <translation>&lt;b&gt;RigMesh Studio&lt;/b&gt;&lt;p&gt;Skizzieren Sie eine Silhouette und erhalten Sie ein geriggtes Teil: Oberfläche, Skelett und Skin-Gewichte, nach Borosán et al., &lt;i&gt;RigMesh&lt;/i&gt;, SIGGRAPH Asia 2012.&lt;/p&gt;&lt;p&gt;GPL-3.0-or-later.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
    <message>
        <source>Properties</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>Skin Weights</source>
        <translation>Skin-Gewichte</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&lt;original&gt;</source>
        <translation>&lt;Original&gt;</translation>
    </message>
    <message>
        <source>This tool has no options.</source>
        <translation>Dieses Werkzeug hat keine Optionen.</translation>
    </message>
    <message>
        <source>Tool Options</source>
        <translation>Werkzeugoptionen</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>&amp;Animation</translation>
    </message>
    <message>
        <source>&amp;Play / Pause</source>
        <translation>&amp;Abspielen / Pause</translation>
    </message>
    <message>
        <source>Pre&amp;vious Frame</source>
        <translation>&amp;Vorheriges Bild</translation>
    </message>
    <message>
        <source>&amp;Next Frame</source>
        <translation>&amp;Nächstes Bild</translation>
    </message>
    <message>
        <source>Jump to &amp;Start</source>
        <translation>Zum &amp;Anfang springen</translation>
    </message>
    <message>
        <source>Jump to &amp;End</source>
        <translation>Zum &amp;Ende springen</translation>
    </message>
    <message>
        <source>&amp;Insert Key</source>
        <translation>Schlüsselbild &amp;einfügen</translation>
    </message>
    <message>
        <source>%1[*] - RigMesh Studio</source>
        <translation>%1[*] – RigMesh Studio</translation>
    </message>
    <message>
        <source>RigMesh Studio</source>
        <translation>RigMesh Studio</translation>
    </message>
    <message>
        <source>Select a part to delete</source>
        <translation>Wählen Sie ein Teil zum Löschen aus</translation>
    </message>
    <message>
        <source>The new language applies when RigMesh Studio starts again.</source>
        <translation>Die neue Sprache gilt ab dem nächsten Start von RigMesh Studio.</translation>
    </message>
    <message>
        <source>&amp;Auto-Rig Part</source>
        <translation>Teil &amp;automatisch riggen</translation>
    </message>
    <message>
        <source>Give the selected part without a skeleton (an imported mesh) a skeleton from its shape and skin weights</source>
        <translation>Dem ausgewählten Teil ohne Skelett (einem importierten Netz) ein Skelett aus seiner Form und Skin-Gewichte geben</translation>
    </message>
    <message>
        <source>Co&amp;nnect Bone</source>
        <translation>Knochen &amp;verbinden</translation>
    </message>
    <message>
        <source>Move the selected bone&apos;s head onto its parent&apos;s tail, as Blender&apos;s Connected does (cut and merge need connected bones)</source>
        <translation>Den Kopf des gewählten Knochens auf das Ende seines Elternknochens setzen, wie Blenders „Verbunden“ (Schneiden und Zusammenfügen brauchen verbundene Knochen)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MergeTool</name>
    <message>
        <source>Drag the part into another to merge them</source>
        <translation>Ziehen Sie das Teil in ein anderes, um sie zusammenzuführen</translation>
    </message>
    <message>
        <source>%1 (%2 ms in all)</source>
        <translation>%1 (insgesamt %2 ms)</translation>
    </message>
    <message>
        <source>Not merged: %1</source>
        <translation>Nicht zusammengeführt: %1</translation>
    </message>
    <message>
        <source>Merge cancelled</source>
        <translation>Zusammenführen abgebrochen</translation>
    </message>
    <message>
        <source>Merge</source>
        <translation>Zusammenführen</translation>
    </message>
    <message>
        <source>Merge: drag a part into another; release over the lit joints to snap, split or connect them (Shift + release splits, Ctrl + release connects at once); Esc cancels</source>
        <translation>Zusammenführen: ziehen Sie ein Teil in ein anderes; lassen Sie über den hervorgehobenen Gelenken los, um sie einzurasten, zu teilen oder zu verbinden (Umschalt + Loslassen teilt, Strg + Loslassen verbindet sofort); Esc bricht ab</translation>
    </message>
    <message>
        <source>Snap %1 of %2 onto %3 of %4 (Esc: cancel)</source>
        <translation>%1 von %2 an %3 von %4 einrasten (Esc: abbrechen)</translation>
    </message>
    <message>
        <source>Split a bone of %1 and snap %2 of %3 there (Esc: cancel)</source>
        <translation>Einen Knochen von %1 teilen und %2 von %3 dort einrasten (Esc: abbrechen)</translation>
    </message>
    <message>
        <source>Connect %1 of %2 to %3 of %4 by a new bone (Esc: cancel)</source>
        <translation>%1 von %2 mit %3 von %4 durch einen neuen Knochen verbinden (Esc: abbrechen)</translation>
    </message>
    <message>
        <source>&amp;Snap the joints together</source>
        <translation>Gelenke &amp;einrasten</translation>
    </message>
    <message>
        <source>S&amp;plit the bone here</source>
        <translation>Knochen hier &amp;teilen</translation>
    </message>
    <message>
        <source>&amp;Connect by a new bone</source>
        <translation>Durch neuen Knochen &amp;verbinden</translation>
    </message>
    <message>
        <source>Cancel (Esc)</source>
        <translation>Abbrechen (Esc)</translation>
    </message>
    <message>
        <source>Merging %1 into %2</source>
        <translation>%1 wird mit %2 zusammengeführt</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MouseBindings</name>
    <message>
        <source>Alt + left drag orbits, Alt + middle drag pans, Alt + right drag or the wheel zooms</source>
        <translation>Alt + Linksziehen kreist, Alt + Mittelziehen verschiebt, Alt + Rechtsziehen oder das Mausrad zoomt</translation>
    </message>
    <message>
        <source>middle drag orbits, Shift + middle drag pans, Ctrl + middle drag or the wheel zooms</source>
        <translation>Mittelziehen kreist, Umschalt + Mittelziehen verschiebt, Strg + Mittelziehen oder das Mausrad zoomt</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::MouseHint</name>
    <message>
        <source>&lt;b&gt;Alt + left-drag&lt;/b&gt; orbits the view, &lt;b&gt;Alt + middle-drag&lt;/b&gt; pans, &lt;b&gt;Alt + right-drag&lt;/b&gt; zooms&lt;br&gt;</source>
        <translation>&lt;b&gt;Alt + Linksziehen&lt;/b&gt; kreist um die Ansicht, &lt;b&gt;Alt + Mittelziehen&lt;/b&gt; verschiebt sie, &lt;b&gt;Alt + Rechtsziehen&lt;/b&gt; zoomt&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Middle-drag&lt;/b&gt; orbits the view, &lt;b&gt;Shift + middle-drag&lt;/b&gt; pans&lt;br&gt;</source>
        <translation>&lt;b&gt;Mittelziehen&lt;/b&gt; kreist um die Ansicht, &lt;b&gt;Umschalt + Mittelziehen&lt;/b&gt; verschiebt sie&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Left-drag&lt;/b&gt; draws a part with the Sketch tool (S), moves it with Select (Q), bends a joint or bone with Pose (P)&lt;br&gt;</source>
        <translation>&lt;b&gt;Linksziehen&lt;/b&gt; zeichnet mit dem Skizzen-Werkzeug (S) ein Teil, verschiebt es mit Auswählen (Q), beugt mit Posieren (P) ein Gelenk oder einen Knochen&lt;br&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Wheel&lt;/b&gt; zooms, &lt;b&gt;Home&lt;/b&gt; frames everything&lt;br&gt;&lt;small&gt;Click to close; Help &amp;gt; Mouse Gestures shows this again&lt;/small&gt;</source>
        <translation>&lt;b&gt;Mausrad&lt;/b&gt; zoomt, &lt;b&gt;Pos1&lt;/b&gt; zeigt alles&lt;br&gt;&lt;small&gt;Zum Schließen klicken; Hilfe &amp;gt; Mausgesten zeigt dies wieder&lt;/small&gt;</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::OutlinerPanel</name>
    <message>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PaintTool</name>
    <message>
        <source>Paint Weights: select a joint (its bone is painted, shown red to blue), then drag over the part; Ctrl + click samples a vertex; Tool Options set the brush; Esc puts the stroke back</source>
        <translation>Gewichte malen: wählen Sie ein Gelenk aus (sein Knochen wird gemalt, dargestellt von Rot bis Blau), dann ziehen Sie über das Teil; Strg + Klick nimmt einen Vertex auf; die Werkzeugoptionen stellen den Pinsel ein; Esc nimmt den Strich zurück</translation>
    </message>
    <message>
        <source>%1 is locked: unlock it in the Skin Weights panel to paint it</source>
        <translation>%1 ist gesperrt: entsperren Sie ihn im Bereich Skin-Gewichte, um ihn zu malen</translation>
    </message>
    <message>
        <source>Sampled %1 = %2 at vertex %3: the Replace brush paints it</source>
        <translation>%1 = %2 bei Vertex %3 aufgenommen: der Pinsel „Ersetzen“ malt diesen Wert</translation>
    </message>
    <message>
        <source>The stroke changed no weights: every other bone there is locked</source>
        <translation>Der Strich hat keine Gewichte geändert: alle anderen Knochen dort sind gesperrt</translation>
    </message>
    <message>
        <source>The stroke changed no weights: they are already as it paints</source>
        <translation>Der Strich hat keine Gewichte geändert: sie sind bereits so, wie er malt</translation>
    </message>
    <message numerus="yes">
        <source>Painted %n dab(s), %1 vertices changed</source>
        <translation>
            <numerusform>%n Tupfer gemalt, %1 Vertices geändert</numerusform>
            <numerusform>%n Tupfer gemalt, %1 Vertices geändert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) skipped: every other bone there is locked</source>
        <translation>
            <numerusform>; %n Vertex-Besuch übersprungen: alle anderen Knochen dort sind gesperrt</numerusform>
            <numerusform>; %n Vertex-Besuche übersprungen: alle anderen Knochen dort sind gesperrt</numerusform>
        </translation>
    </message>
    <message>
        <source>Stroke put back</source>
        <translation>Strich zurückgenommen</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Subtract</source>
        <translation>Abziehen</translation>
    </message>
    <message>
        <source>Replace</source>
        <translation>Ersetzen</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Glätten</translation>
    </message>
    <message>
        <source>Brush</source>
        <translation>Pinsel</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Sharp</source>
        <translation>Spitz</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Konstant</translation>
    </message>
    <message>
        <source>How the brush&apos;s strength falls off from its centre to its rim</source>
        <translation>Wie die Stärke des Pinsels von der Mitte zum Rand abnimmt</translation>
    </message>
    <message>
        <source>Falloff</source>
        <translation>Abnahme</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Strength</source>
        <translation>Stärke</translation>
    </message>
    <message>
        <source>The weight the Replace brush paints towards (Ctrl + click samples)</source>
        <translation>Das Gewicht, zu dem der Pinsel „Ersetzen“ hin malt (Strg + Klick nimmt es auf)</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Front faces only</source>
        <translation>Nur Vorderseiten</translation>
    </message>
    <message>
        <source>Off: the brush also paints the far side of the part, through it</source>
        <translation>Aus: der Pinsel malt durch das Teil hindurch auch seine Rückseite</translation>
    </message>
    <message>
        <source>Paint Weights</source>
        <translation>Gewichte malen</translation>
    </message>
    <message>
        <source>Select a joint first: its bone is the one painted</source>
        <translation>Wählen Sie zuerst ein Gelenk aus: Sein Knochen wird gemalt</translation>
    </message>
    <message>
        <source>The stroke did not pass over %1: nothing painted</source>
        <translation>Der Strich ging nicht über %1: nichts gemalt</translation>
    </message>
    <message>
        <source>The stroke changed no weights: %1 has one bone only, whose weight is 1 everywhere</source>
        <translation>Der Strich hat keine Gewichte geändert: %1 hat nur einen Knochen, dessen Gewicht überall 1 ist</translation>
    </message>
    <message>
        <source>X-mirror (left and right)</source>
        <translation>X-Spiegelung (links und rechts)</translation>
    </message>
    <message>
        <source>Also paints the other side, about the part&apos;s left-right mirror plane, on the bone&apos;s mirror image (Blender&apos;s X-mirror)</source>
        <translation>Malt auch die andere Seite, an der Links-rechts-Spiegelebene des Teils, auf das Spiegelbild des Knochens (Blenders X-Spiegelung)</translation>
    </message>
    <message numerus="yes">
        <source>; %n vertex visit(s) painted on one side only: no mirror partner there</source>
        <translation>
            <numerusform>; %n Vertex-Besuch nur auf einer Seite gemalt: dort kein Spiegelpartner</numerusform>
            <numerusform>; %n Vertex-Besuche nur auf einer Seite gemalt: dort kein Spiegelpartner</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PoseController</name>
    <message>
        <source>&amp;Mirror Pose</source>
        <translation>Pose &amp;spiegeln</translation>
    </message>
    <message>
        <source>&amp;Reset Pose</source>
        <translation>Pose &amp;zurücksetzen</translation>
    </message>
    <message>
        <source>Select a part to reset its pose</source>
        <translation>Wählen Sie ein Teil aus, um seine Pose zurückzusetzen</translation>
    </message>
    <message>
        <source>Select a part to mirror its pose</source>
        <translation>Wählen Sie ein Teil aus, um seine Pose zu spiegeln</translation>
    </message>
    <message>
        <source>%1 has no skeleton to pose</source>
        <translation>%1 hat kein Skelett zum Posieren</translation>
    </message>
    <message>
        <source>%1 has no left-right mirror plane: its two sides differ too much to mirror its pose</source>
        <translation>%1 hat keine Links-rechts-Spiegelebene: Seine beiden Seiten unterscheiden sich zu sehr, um seine Pose zu spiegeln</translation>
    </message>
    <message>
        <source>Mirror Pose of %1</source>
        <translation>Pose von %1 spiegeln</translation>
    </message>
    <message>
        <source>Mirrored the pose of %1 left to right</source>
        <translation>Pose von %1 von links nach rechts gespiegelt</translation>
    </message>
    <message>
        <source>Flip the selected part&apos;s pose left to right about its mirror plane, as Blender&apos;s Paste Pose Flipped</source>
        <translation>Spiegelt die Pose des ausgewählten Teils von links nach rechts an seiner Spiegelebene, wie Blenders „Pose gespiegelt einfügen“</translation>
    </message>
    <message>
        <source>Put the selected part back in its rest pose</source>
        <translation>Setzt das ausgewählte Teil in seine Ruhepose zurück</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PoseTool</name>
    <message>
        <source>Pose: drag a joint (IK, this limb only); Alt + drag reaches through the whole body; drag a bone, Ctrl + drag the joint it ends at or drag the selected bone&apos;s ring to turn it (FK); Shift + click pins or unpins a joint</source>
        <translation>Posieren: ziehen Sie ein Gelenk (IK, nur diese Gliedmaße); Alt + Ziehen reicht durch den ganzen Körper; ziehen Sie einen Knochen, mit Strg das Gelenk an seinem Ende oder den Ring des ausgewählten Knochens, um ihn zu drehen (FK); Umschalt + Klick fixiert ein Gelenk oder löst es</translation>
    </message>
    <message>
        <source>Click on a joint or a bone to pose the part</source>
        <translation>Klicken Sie auf ein Gelenk oder einen Knochen, um das Teil zu posieren</translation>
    </message>
    <message>
        <source>The root joint ends no bone: drag its ring to turn the whole part, or drag it without Ctrl to move the part</source>
        <translation>Am Wurzelgelenk endet kein Knochen: ziehen Sie seinen Ring, um das ganze Teil zu drehen, oder ziehen Sie es ohne Strg, um das Teil zu verschieben</translation>
    </message>
    <message>
        <source>IK reaches through the whole body</source>
        <translation>IK reicht durch den ganzen Körper</translation>
    </message>
    <message>
        <source>Off: a drag moves the limb up to the nearest junction or pinned joint. Alt + drag does the other for one drag.</source>
        <translation>Aus: Ziehen bewegt die Gliedmaße bis zur nächsten Verzweigung oder zum nächsten fixierten Gelenk. Alt + Ziehen macht für einen Zug das andere.</translation>
    </message>
    <message>
        <source>Pose</source>
        <translation>Posieren</translation>
    </message>
    <message>
        <source>Not posed: %1</source>
        <translation>Nicht posiert: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PreferencesDialog</name>
    <message>
        <source>Preferences</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>System default (%1)</source>
        <translation>Systemvorgabe (%1)</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>The target edge length of each new sketch; Automatic takes the document&apos;s (its first sketched part&apos;s), or for the first part one from the sketch&apos;s size</source>
        <translation>Die Ziel-Kantenlänge jeder neuen Skizze; „Automatisch“ übernimmt die des Dokuments (seines ersten skizzierten Teils) oder für das erste Teil eine aus der Größe der Skizze</translation>
    </message>
    <message>
        <source>Dual quaternion</source>
        <translation>Duale Quaternionen</translation>
    </message>
    <message>
        <source>Linear blend</source>
        <translation>Lineare Überblendung</translation>
    </message>
    <message>
        <source>How the view deforms posed parts (View &gt; Dual Quaternion Skinning)</source>
        <translation>Wie die Ansicht posierte Teile verformt (Ansicht &gt; Dual-Quaternion-Skinning)</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Seconds from the last change until unsaved work is written to the recovery file</source>
        <translation>Sekunden nach der letzten Änderung, bis ungespeicherte Arbeit in die Wiederherstellungsdatei geschrieben wird</translation>
    </message>
    <message>
        <source>Blender</source>
        <translation>Blender</translation>
    </message>
    <message>
        <source>Maya</source>
        <translation>Maya</translation>
    </message>
    <message>
        <source>Light</source>
        <translation>Hell</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Dunkel</translation>
    </message>
    <message>
        <source>&amp;Language:</source>
        <translation>&amp;Sprache:</translation>
    </message>
    <message>
        <source>Default &amp;edge length:</source>
        <translation>Standard-&amp;Kantenlänge:</translation>
    </message>
    <message>
        <source>&amp;Skinning:</source>
        <translation>S&amp;kinning:</translation>
    </message>
    <message>
        <source>&amp;Autosave after:</source>
        <translation>Automatisch &amp;speichern nach:</translation>
    </message>
    <message>
        <source>&amp;Mouse bindings:</source>
        <translation>&amp;Maustasten:</translation>
    </message>
    <message>
        <source>&amp;Theme:</source>
        <translation>&amp;Design:</translation>
    </message>
    <message>
        <source>A new language applies when RigMesh Studio starts again.</source>
        <translation>Eine neue Sprache gilt ab dem nächsten Start von RigMesh Studio.</translation>
    </message>
    <message>
        <source>Alt + drag is the view&apos;s, so the Pose tool reaches through the whole body with its Tool Options box</source>
        <translation>Alt + Ziehen gehört der Ansicht, daher reicht das Posieren-Werkzeug über das Kästchen in seinen Werkzeugoptionen durch den ganzen Körper</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::PropertiesPanel</name>
    <message>
        <source>Rebuild</source>
        <translation>Neu bauen</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>Target edge length of the surface; automatic = 1/60 of the sketch&apos;s size</source>
        <translation>Ziel-Kantenlänge der Oberfläche; automatisch = 1/60 der Größe der Skizze</translation>
    </message>
    <message>
        <source>Least-squares smoothing</source>
        <translation>Glättung nach kleinsten Quadraten</translation>
    </message>
    <message>
        <source>Edge length</source>
        <translation>Kantenlänge</translation>
    </message>
    <message>
        <source>Bone rotation (XYZ Euler)</source>
        <translation>Knochenrotation (XYZ-Euler)</translation>
    </message>
    <message>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <source>The rotation from rest, in degrees, of the bone ending at the selected joint about its head, relative to its parent bone; at the root, of the whole part about the root</source>
        <translation>Die Rotation aus der Ruheposition in Grad, des am ausgewählten Gelenk endenden Knochens um seinen Kopf, relativ zu seinem Elternknochen; an der Wurzel die des ganzen Teils um die Wurzel</translation>
    </message>
    <message>
        <source>No part selected</source>
        <translation>Kein Teil ausgewählt</translation>
    </message>
    <message>
        <source>Select a part in the viewport or the outliner.</source>
        <translation>Wählen Sie ein Teil im 3D-Fenster oder in der Gliederung aus.</translation>
    </message>
    <message>
        <source>stroke of %1 points</source>
        <translation>Strich aus %1 Punkten</translation>
    </message>
    <message>
        <source>made by merging or importing: no stroke to rebuild from</source>
        <translation>durch Zusammenführen oder Importieren entstanden: kein Strich zum Neubauen</translation>
    </message>
    <message>
        <source>Root joint %1: whole part (XYZ Euler)</source>
        <translation>Wurzelgelenk %1: ganzes Teil (XYZ-Euler)</translation>
    </message>
    <message>
        <source>Bone to joint %1 (XYZ Euler)</source>
        <translation>Knochen zu Gelenk %1 (XYZ-Euler)</translation>
    </message>
    <message>
        <source>Not posed: %1</source>
        <translation>Nicht posiert: %1</translation>
    </message>
    <message>
        <source>%1 has hand-painted skin weights. Rebuilding recomputes them from the sketch and the painting is lost (Undo brings it back). Rebuild anyway?</source>
        <translation>%1 hat von Hand gemalte Skin-Gewichte. Neu bauen berechnet sie aus der Skizze neu, und das Gemalte geht verloren (Rückgängig holt es zurück). Trotzdem neu bauen?</translation>
    </message>
    <message>
        <source>Not rebuilt: the painted weights are kept</source>
        <translation>Nicht neu gebaut: die gemalten Gewichte bleiben erhalten</translation>
    </message>
    <message>
        <source>Rebuilt %1</source>
        <translation>%1 neu gebaut</translation>
    </message>
    <message>
        <source>Rebuilt %1; %2</source>
        <translation>%1 neu gebaut; %2</translation>
    </message>
    <message>
        <source>Not rebuilt: %1</source>
        <translation>Nicht neu gebaut: %1</translation>
    </message>
    <message>
        <source>Select a part to rebuild</source>
        <translation>Wählen Sie ein Teil zum Neubauen aus</translation>
    </message>
    <message>
        <source>Rebuilding %1</source>
        <translation>%1 wird neu gebaut</translation>
    </message>
    <message>
        <source>Rebuild of %1 cancelled</source>
        <translation>Neubau von %1 abgebrochen</translation>
    </message>
    <message>
        <source>
Not rigged: imported as a static mesh. Tools &gt; Auto-Rig Part gives it a skeleton and skin weights.</source>
        <translation>
Nicht geriggt: als statisches Netz importiert. Werkzeuge &gt; Teil automatisch riggen gibt ihm ein Skelett und Skin-Gewichte.</translation>
    </message>
    <message>
        <source>%1 vertices, %2 faces
%3, %4
</source>
        <translation>%1 Vertices, %2 Flächen
%3, %4
</translation>
    </message>
    <message>
        <source>1 joint</source>
        <translation>1 Gelenk</translation>
    </message>
    <message>
        <source>%1 joints</source>
        <translation>%1 Gelenke</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 Knochen</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 Knochen</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::RigController</name>
    <message>
        <source>Select a part to rig first</source>
        <translation>Wählen Sie zuerst ein Teil zum Riggen aus</translation>
    </message>
    <message>
        <source>%1 already has a skeleton; Auto-Rig is for parts without one, such as imported meshes</source>
        <translation>%1 hat bereits ein Skelett; automatisches Riggen ist für Teile ohne Skelett, etwa importierte Netze</translation>
    </message>
    <message>
        <source>Rigging %1</source>
        <translation>%1 wird geriggt</translation>
    </message>
    <message>
        <source>Cannot rig %1</source>
        <translation>%1 kann nicht geriggt werden</translation>
    </message>
    <message>
        <source>Rigging %1 cancelled</source>
        <translation>Riggen von %1 abgebrochen</translation>
    </message>
    <message>
        <source>Imported without a rig</source>
        <translation>Ohne Rig importiert</translation>
    </message>
    <message>
        <source>Rig Now</source>
        <translation>Jetzt riggen</translation>
    </message>
    <message>
        <source>Not Now</source>
        <translation>Nicht jetzt</translation>
    </message>
    <message>
        <source>Auto-Rig gives the imported meshes one skeleton from their shape and skin weights, so the figure can be posed, animated and painted like a sketched part. You can also do it later with Tools &gt; Auto-Rig Part.</source>
        <translation>Automatisches Riggen gibt den importierten Netzen ein Skelett aus ihrer Form und Skin-Gewichte, sodass sich die Figur wie ein skizziertes Teil posieren, animieren und bemalen lässt. Sie können das auch später mit Werkzeuge &gt; Teil automatisch riggen tun.</translation>
    </message>
    <message>
        <source>Select the joint of the bone to connect first</source>
        <translation>Wählen Sie zuerst das Gelenk des zu verbindenden Knochens</translation>
    </message>
    <message>
        <source>The selected joint ends no bone</source>
        <translation>Am gewählten Gelenk endet kein Knochen</translation>
    </message>
    <message>
        <source>Bone not connected: %1</source>
        <translation>Knochen nicht verbunden: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::SelectTool</name>
    <message>
        <source>Select: click a part or a joint (with a weight view on, the click pins the vertex&apos;s weights in the Skin Weights panel); drag a part to move it, Ctrl + drag to turn it</source>
        <translation>Auswählen: klicken Sie auf ein Teil oder ein Gelenk (bei eingeschalteter Gewichtsansicht heftet der Klick die Gewichte des Vertex im Bereich Skin-Gewichte an); ziehen Sie ein Teil, um es zu verschieben, Strg + Ziehen dreht es</translation>
    </message>
    <message>
        <source>Select</source>
        <translation>Auswählen</translation>
    </message>
    <message>
        <source>%1 overlaps %2: moving does not join parts; the Merge tool (M) merges them</source>
        <translation>%1 überlappt %2: Verschieben verbindet keine Teile; das Zusammenführen-Werkzeug (M) führt sie zusammen</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::ShortcutToolTips</name>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::SketchTool</name>
    <message>
        <source>Sketch: drag with the left button to draw a closed silhouette; release to inflate it into a rigged part</source>
        <translation>Skizze: ziehen Sie mit der linken Maustaste eine geschlossene Silhouette; beim Loslassen wird sie zu einem geriggten Teil aufgeblasen</translation>
    </message>
    <message>
        <source>That stroke is too short: drag to draw a closed outline</source>
        <translation>Der Strich ist zu kurz: ziehen Sie, um einen geschlossenen Umriss zu zeichnen</translation>
    </message>
    <message>
        <source>Sketch</source>
        <translation>Skizze</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::TimelineDock</name>
    <message>
        <source>Jump to start (Shift+Left)</source>
        <translation>Zum Anfang springen (Umschalt+Links)</translation>
    </message>
    <message>
        <source>Previous frame (Left)</source>
        <translation>Vorheriges Bild (Links)</translation>
    </message>
    <message>
        <source>Play / pause (Space)</source>
        <translation>Abspielen / Pause (Leertaste)</translation>
    </message>
    <message>
        <source>Next frame (Right)</source>
        <translation>Nächstes Bild (Rechts)</translation>
    </message>
    <message>
        <source>Jump to end (Shift+Right)</source>
        <translation>Zum Ende springen (Umschalt+Rechts)</translation>
    </message>
    <message>
        <source>Current frame</source>
        <translation>Aktuelles Bild</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Anfang</translation>
    </message>
    <message>
        <source>First frame of the range</source>
        <translation>Erstes Bild des Bereichs</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Ende</translation>
    </message>
    <message>
        <source>Last frame of the range</source>
        <translation>Letztes Bild des Bereichs</translation>
    </message>
    <message>
        <source> fps</source>
        <translation> fps</translation>
    </message>
    <message>
        <source>Frame rate: keys stay on their frames when it changes</source>
        <translation>Bildrate: Schlüsselbilder bleiben bei einer Änderung auf ihren Bildern</translation>
    </message>
    <message>
        <source>Clip</source>
        <translation>Clip</translation>
    </message>
    <message>
        <source>The clip the part keys and plays</source>
        <translation>Der Clip, in den das Teil Schlüsselbilder setzt und den es abspielt</translation>
    </message>
    <message>
        <source>New, duplicate, rename or delete clips</source>
        <translation>Clips anlegen, duplizieren, umbenennen oder löschen</translation>
    </message>
    <message>
        <source>Clip name:</source>
        <translation>Clipname:</translation>
    </message>
    <message>
        <source>&amp;New Clip...</source>
        <translation>&amp;Neuer Clip …</translation>
    </message>
    <message>
        <source>New Clip</source>
        <translation>Neuer Clip</translation>
    </message>
    <message>
        <source>walk</source>
        <translation>gehen</translation>
    </message>
    <message>
        <source>&amp;Duplicate Clip...</source>
        <translation>Clip &amp;duplizieren …</translation>
    </message>
    <message>
        <source>Duplicate Clip</source>
        <translation>Clip duplizieren</translation>
    </message>
    <message>
        <source>&amp;Rename Clip...</source>
        <translation>Clip &amp;umbenennen …</translation>
    </message>
    <message>
        <source>Rename Clip</source>
        <translation>Clip umbenennen</translation>
    </message>
    <message>
        <source>D&amp;elete Clip</source>
        <translation>Clip &amp;löschen</translation>
    </message>
    <message>
        <source>Interpolation between keys</source>
        <translation>Interpolation zwischen Schlüsselbildern</translation>
    </message>
    <message>
        <source>Constant</source>
        <translation>Konstant</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Smooth</source>
        <translation>Weich</translation>
    </message>
    <message>
        <source>Before the first and after the last key</source>
        <translation>Vor dem ersten und nach dem letzten Schlüsselbild</translation>
    </message>
    <message>
        <source>Hold</source>
        <translation>Halten</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Ping-Pong</source>
        <translation>Ping-Pong</translation>
    </message>
    <message>
        <source>● Auto Key</source>
        <translation>● Auto-Key</translation>
    </message>
    <message>
        <source>Key every pose change at the current frame</source>
        <translation>Jede Posenänderung im aktuellen Bild als Schlüsselbild setzen</translation>
    </message>
    <message>
        <source>Onion Skin</source>
        <translation>Zwiebelhaut</translation>
    </message>
    <message>
        <source>Show the previous and next keyed poses as ghosts</source>
        <translation>Die vorige und die nächste Pose mit Schlüsselbild als Geister zeigen</translation>
    </message>
    <message>
        <source>Clip of %1</source>
        <translation>Clip von %1</translation>
    </message>
    <message>
        <source>Frame range not set: %1</source>
        <translation>Bildbereich nicht gesetzt: %1</translation>
    </message>
    <message>
        <source>Clip not changed: %1</source>
        <translation>Clip nicht geändert: %1</translation>
    </message>
    <message>
        <source>No new clip: %1</source>
        <translation>Kein neuer Clip: %1</translation>
    </message>
    <message>
        <source>Not duplicated: %1</source>
        <translation>Nicht dupliziert: %1</translation>
    </message>
    <message>
        <source>Not renamed: %1</source>
        <translation>Nicht umbenannt: %1</translation>
    </message>
    <message>
        <source>Not deleted: %1</source>
        <translation>Nicht gelöscht: %1</translation>
    </message>
    <message>
        <source>Clip not chosen: %1</source>
        <translation>Clip nicht gewählt: %1</translation>
    </message>
    <message>
        <source>Nothing to key: no part has a skeleton</source>
        <translation>Nichts für ein Schlüsselbild: kein Teil hat ein Skelett</translation>
    </message>
    <message numerus="yes">
        <source>Keyed %n part(s) at frame %1</source>
        <translation>
            <numerusform>Schlüsselbild für %n Teil bei Bild %1 gesetzt</numerusform>
            <numerusform>Schlüsselbilder für %n Teile bei Bild %1 gesetzt</numerusform>
        </translation>
    </message>
    <message>
        <source>Not keyed: %1</source>
        <translation>Kein Schlüsselbild gesetzt: %1</translation>
    </message>
    <message>
        <source>Select keys to delete</source>
        <translation>Wählen Sie die zu löschenden Schlüsselbilder aus</translation>
    </message>
    <message numerus="yes">
        <source>Deleted %n key(s)</source>
        <translation>
            <numerusform>%n Schlüsselbild gelöscht</numerusform>
            <numerusform>%n Schlüsselbilder gelöscht</numerusform>
        </translation>
    </message>
    <message>
        <source>Select keys to copy</source>
        <translation>Wählen Sie die zu kopierenden Schlüsselbilder aus</translation>
    </message>
    <message numerus="yes">
        <source>Copied %n key(s)</source>
        <translation>
            <numerusform>%n Schlüsselbild kopiert</numerusform>
            <numerusform>%n Schlüsselbilder kopiert</numerusform>
        </translation>
    </message>
    <message>
        <source>Copy keys first (Ctrl+C in the timeline)</source>
        <translation>Kopieren Sie zuerst Schlüsselbilder (Strg+C in der Zeitleiste)</translation>
    </message>
    <message>
        <source>Nothing pasted: the copied parts are gone</source>
        <translation>Nichts eingefügt: die kopierten Teile gibt es nicht mehr</translation>
    </message>
    <message>
        <source>Pasted at frame %1</source>
        <translation>Bei Bild %1 eingefügt</translation>
    </message>
    <message>
        <source>Not pasted: %1</source>
        <translation>Nicht eingefügt: %1</translation>
    </message>
    <message>
        <source>Delete Keys</source>
        <translation>Schlüsselbilder löschen</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::TimelineView</name>
    <message>
        <source>Frames</source>
        <translation>Bilder</translation>
    </message>
    <message>
        <source>Frame %1 = %2 s</source>
        <translation>Bild %1 = %2 s</translation>
    </message>
    <message>
        <source>Key at frame %1 (%2 s)</source>
        <translation>Schlüsselbild bei Bild %1 (%2 s)</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::UndoStatus</name>
    <message>
        <source>Undone: %1</source>
        <translation>Rückgängig gemacht: %1</translation>
    </message>
    <message>
        <source>Redone: %1</source>
        <translation>Wiederhergestellt: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::UserAction</name>
    <message>
        <source>Internal error: %1</source>
        <translation>Interner Fehler: %1</translation>
    </message>
    <message>
        <source>%1: internal error (%2)</source>
        <translation>%1: interner Fehler (%2)</translation>
    </message>
    <message>
        <source>Out of memory.</source>
        <translation>Nicht genügend Arbeitsspeicher.</translation>
    </message>
    <message>
        <source>%1: out of memory</source>
        <translation>%1: nicht genügend Arbeitsspeicher</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::Viewpoint</name>
    <message>
        <source>&amp;Front</source>
        <translation>&amp;Vorne</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Hinten</translation>
    </message>
    <message>
        <source>&amp;Right</source>
        <translation>&amp;Rechts</translation>
    </message>
    <message>
        <source>&amp;Left</source>
        <translation>&amp;Links</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Oben</translation>
    </message>
    <message>
        <source>B&amp;ottom</source>
        <translation>&amp;Unten</translation>
    </message>
    <message>
        <source>View&amp;point</source>
        <translation>&amp;Blickpunkt</translation>
    </message>
    <message>
        <source>&amp;Orthographic / Perspective</source>
        <translation>Orthografisch / &amp;Perspektivisch</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::Viewport</name>
    <message>
        <source>Bone not changed: %1</source>
        <translation>Knochen nicht geändert: %1</translation>
    </message>
    <message>
        <source>Split Bone Here</source>
        <translation>Knochen hier teilen</translation>
    </message>
    <message>
        <source>Delete Bone</source>
        <translation>Knochen löschen</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL %1.%2 (core profile), which the &quot;%3&quot; display platform does not provide. Run RigMesh Studio on a desktop (X11 or Wayland) or under xvfb-run.</source>
        <translation>Die 3D-Ansicht braucht OpenGL %1.%2 (Core-Profil), das die Anzeigeplattform „%3“ nicht bietet. Starten Sie RigMesh Studio auf einem Desktop (X11 oder Wayland) oder unter xvfb-run.</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL %1.%2, but the &quot;%3&quot; platform gives OpenGL %4.%5.</source>
        <translation>Die 3D-Ansicht braucht OpenGL %1.%2, die Plattform „%3“ bietet aber OpenGL %4.%5.</translation>
    </message>
    <message>
        <source>OpenGL 3.3 shaders failed: %1</source>
        <translation>OpenGL-3.3-Shader fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Vertex %1 of %2: no weights</source>
        <translation>Vertex %1 von %2: keine Gewichte</translation>
    </message>
    <message>
        <source>bone %1 (to %2)</source>
        <translation>Knochen %1 (bis %2)</translation>
    </message>
    <message>
        <source>Vertex %1 of %2: %3</source>
        <translation>Vertex %1 von %2: %3</translation>
    </message>
    <message>
        <source>Point at a bone: K splits it there, Shift+K deletes it</source>
        <translation>Zeigen Sie auf einen Knochen: K teilt ihn dort, Umschalt+K löscht ihn</translation>
    </message>
    <message>
        <source>Connect Bone</source>
        <translation>Knochen verbinden</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightViewChooser</name>
    <message>
        <source>&amp;Weights</source>
        <translation>&amp;Gewichte</translation>
    </message>
    <message>
        <source>&amp;Off</source>
        <translation>&amp;Aus</translation>
    </message>
    <message>
        <source>&amp;Selected Bone (select its joint)</source>
        <translation>&amp;Ausgewählter Knochen (sein Gelenk auswählen)</translation>
    </message>
    <message>
        <source>&amp;Dominant Bone</source>
        <translation>&amp;Dominanter Knochen</translation>
    </message>
    <message>
        <source>&amp;Influence Count</source>
        <translation>Anzahl der &amp;Einflüsse</translation>
    </message>
    <message>
        <source>Difference from &amp;Global Weights</source>
        <translation>Abweichung von den &amp;globalen Gewichten</translation>
    </message>
    <message>
        <source>Weight View</source>
        <translation>Gewichtsansicht</translation>
    </message>
    <message>
        <source> Weights: </source>
        <translation> Gewichte: </translation>
    </message>
    <message>
        <source>Colour the surface by its skin weights (View &gt; Weights)</source>
        <translation>Oberfläche nach ihren Skin-Gewichten einfärben (Ansicht &gt; Gewichte)</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsController</name>
    <message>
        <source>Recompute Weights</source>
        <translation>Gewichte neu berechnen</translation>
    </message>
    <message>
        <source>Weigh&amp;ts</source>
        <translation>Ge&amp;wichte</translation>
    </message>
    <message>
        <source>Select a part first</source>
        <translation>Wählen Sie zuerst ein Teil aus</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n vertices changed</source>
        <translation>
            <numerusform>%1: %n Vertex geändert</numerusform>
            <numerusform>%1: %n Vertices geändert</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Normalize All</source>
        <translation>Alle &amp;normalisieren</translation>
    </message>
    <message>
        <source>&amp;Clean (below 0.01)</source>
        <translation>&amp;Bereinigen (unter 0,01)</translation>
    </message>
    <message>
        <source>&amp;Limit Total (4 bones)</source>
        <translation>Gesamtzahl &amp;begrenzen (4 Knochen)</translation>
    </message>
    <message>
        <source>&amp;Smooth All</source>
        <translation>Alle &amp;glätten</translation>
    </message>
    <message>
        <source>Every unlocked bone&apos;s weight halfway towards its neighbours&apos; mean</source>
        <translation>Das Gewicht jedes nicht gesperrten Knochens halb zum Mittel seiner Nachbarn hin</translation>
    </message>
    <message>
        <source>&amp;Recompute Weights (Bone Heat)</source>
        <translation>Gewichte neu &amp;berechnen (Knochenwärme)</translation>
    </message>
    <message>
        <source>Bone heat over the whole part again, as a new sketch gets it; locked bones keep their weights</source>
        <translation>Knochenwärme erneut über das ganze Teil, wie eine neue Skizze sie bekommt; gesperrte Knochen behalten ihre Gewichte</translation>
    </message>
    <message>
        <source>Check &amp;Rig</source>
        <translation>&amp;Rig prüfen</translation>
    </message>
    <message>
        <source>%1 has no skeleton, so it has no weights to recompute</source>
        <translation>%1 hat kein Skelett und daher keine Gewichte zum Neuberechnen</translation>
    </message>
    <message>
        <source>The weights of %1 were painted or cleaned up by hand. Recomputing them by bone heat replaces that work (locked bones keep theirs; Undo brings it back). Recompute anyway?</source>
        <translation>Die Gewichte von %1 wurden von Hand gemalt oder bereinigt. Sie mit Knochenwärme neu zu berechnen ersetzt diese Arbeit (gesperrte Knochen behalten ihre; Rückgängig holt sie zurück). Trotzdem neu berechnen?</translation>
    </message>
    <message>
        <source>Weights not recomputed: the painted weights are kept</source>
        <translation>Gewichte nicht neu berechnet: die gemalten Gewichte bleiben erhalten</translation>
    </message>
    <message>
        <source>Recomputing the weights of %1</source>
        <translation>Gewichte von %1 werden neu berechnet</translation>
    </message>
    <message>
        <source>Weights not recomputed: %1</source>
        <translation>Gewichte nicht neu berechnet: %1</translation>
    </message>
</context>
<context>
    <name>rigmesh::widgets::WeightsPanel</name>
    <message>
        <source>Bone</source>
        <translation>Knochen</translation>
    </message>
    <message>
        <source>Leads</source>
        <translation>Führt</translation>
    </message>
    <message>
        <source>Lock</source>
        <translation>Sperre</translation>
    </message>
    <message>
        <source>Leads: the vertices whose largest weight is the bone&apos;s. Lock: painting and the clean-ups keep the bone&apos;s weights. Click a bone to paint or view it.</source>
        <translation>Führt: die Vertices, deren größtes Gewicht das des Knochens ist. Sperre: Malen und Bereinigen lassen die Gewichte des Knochens unverändert. Klicken Sie auf einen Knochen, um ihn zu malen oder anzuzeigen.</translation>
    </message>
    <message>
        <source>Vertex</source>
        <translation>Vertex</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Locked</source>
        <translation>Gesperrt</translation>
    </message>
    <message>
        <source>Check Rig</source>
        <translation>Rig prüfen</translation>
    </message>
    <message>
        <source>at most </source>
        <translation>höchstens </translation>
    </message>
    <message>
        <source> bones</source>
        <translation> Knochen</translation>
    </message>
    <message>
        <source>Vertices weighted by more bones are listed (glTF takes 4)</source>
        <translation>Vertices mit Gewichten von mehr Knochen werden aufgeführt (glTF nimmt 4)</translation>
    </message>
    <message>
        <source>%1 has no skeleton</source>
        <translation>%1 hat kein Skelett</translation>
    </message>
    <message>
        <source>Select a part to see its bones&apos; weights</source>
        <translation>Wählen Sie ein Teil aus, um die Gewichte seiner Knochen zu sehen</translation>
    </message>
    <message>
        <source>Click a vertex with a weight view on (or Ctrl + click while painting) to pin its weights here.</source>
        <translation>Klicken Sie bei eingeschalteter Gewichtsansicht auf einen Vertex (oder beim Malen mit Strg + Klick), um seine Gewichte hier anzuheften.</translation>
    </message>
    <message numerus="yes">
        <source>Vertex %1 of %2: %n bone(s), sum %3</source>
        <translation>
            <numerusform>Vertex %1 von %2: %n Knochen, Summe %3</numerusform>
            <numerusform>Vertex %1 von %2: %n Knochen, Summe %3</numerusform>
        </translation>
    </message>
    <message>
        <source>locked</source>
        <translation>gesperrt</translation>
    </message>
    <message>
        <source>Select a part to check its rig</source>
        <translation>Wählen Sie ein Teil aus, um sein Rig zu prüfen</translation>
    </message>
    <message>
        <source>Vertex %1</source>
        <translation>Vertex %1</translation>
    </message>
    <message>
        <source>... and %1 more (all marked when the group is clicked)</source>
        <translation>… und %1 weitere (alle markiert, wenn die Gruppe angeklickt wird)</translation>
    </message>
    <message>
        <source>Unweighted vertices: %1</source>
        <translation>Vertices ohne Gewicht: %1</translation>
    </message>
    <message>
        <source>Bones leading no vertex: %1</source>
        <translation>Knochen, die keinen Vertex führen: %1</translation>
    </message>
    <message>
        <source>Vertices over %1 influences: %2</source>
        <translation>Vertices mit mehr als %1 Einflüssen: %2</translation>
    </message>
    <message>
        <source>Vertices whose weights do not sum to 1: %1</source>
        <translation>Vertices, deren Gewichte nicht 1 ergeben: %1</translation>
    </message>
    <message>
        <source>Check Rig: %1 is clean</source>
        <translation>Rig prüfen: %1 ist einwandfrei</translation>
    </message>
    <message>
        <source>Check Rig found problems in %1: click a line to select them</source>
        <translation>„Rig prüfen“ hat Probleme in %1 gefunden: klicken Sie auf eine Zeile, um sie auszuwählen</translation>
    </message>
    <message>
        <source>%1: %2, %3 locked</source>
        <translation>%1: %2, %3 gesperrt</translation>
    </message>
    <message>
        <source>1 bone</source>
        <translation>1 Knochen</translation>
    </message>
    <message>
        <source>%1 bones</source>
        <translation>%1 Knochen</translation>
    </message>
</context>
</TS>
